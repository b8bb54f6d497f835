// The mesh cache's process-wide settings pointed at a folder for one test, restored after; and
// whether two meshes are the same, bit for bit (tests of engine/mesh/mesh_cache.hpp and of the
// meshers that use it).
#pragma once

#include <cstdint>
#include <filesystem>

#include "engine/mesh/mesh_cache.hpp"
#include "engine/mesh/tet_mesh.hpp"

namespace ccm::test {

struct CacheIn {
  MeshCacheSettings saved = mesh_cache_settings();
  explicit CacheIn(const std::filesystem::path& folder,
                   std::uintmax_t max_bytes = std::uintmax_t{1} << 30, bool enabled = true) {
    set_mesh_cache_settings({enabled, folder, max_bytes});
  }
  ~CacheIn() { set_mesh_cache_settings(saved); }
  CacheIn(const CacheIn&) = delete;
  CacheIn& operator=(const CacheIn&) = delete;
};

inline bool same_mesh(const TetMesh& a, const TetMesh& b) {
  return a.nodes == b.nodes && a.tets == b.tets && a.named_surfaces == b.named_surfaces &&
         a.named_node_sets == b.named_node_sets && a.region_names == b.region_names &&
         a.tet_region == b.tet_region;
}

}  // namespace ccm::test
