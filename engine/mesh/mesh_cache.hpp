// Meshes kept on disk by content (docs/mesh-cache.md): a body meshed once is read back, bit for
// bit, however often a scene runs (`ccm compare`'s two runs, a study's points, a calibration).
//
// A mesh is filed under the hash of its key: a text that holds everything the mesh depends on
// (the primitive's fields as exact hexadecimal floats, the Gmsh version, a hash of the mesher's
// source). The file holds the key too, and a read whose key differs is a miss, so a hash collision
// cannot serve a wrong mesh; a checksum of the mesh's bytes catches a damaged file. Files are
// written under a temporary name and renamed into place
// (atomic: two processes that mesh the same body at once both leave one whole file); a file that
// does not read back whole is a miss and is replaced. The folder is kept under a size bound by
// removing the least recently used files.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include "engine/mesh/tet_mesh.hpp"

namespace ccm {

struct MeshCacheSettings {
  bool enabled = true;
  std::filesystem::path folder;                        // empty: the default (mesh_cache_folder)
  std::uintmax_t max_bytes = std::uintmax_t{2} << 30;  // 2 GiB
};

// $CCM_MESH_CACHE when set (a folder), else $XDG_CACHE_HOME/ccm/meshes, else
// $HOME/.cache/ccm/meshes, else a folder under the system's temporary directory.
std::filesystem::path default_mesh_cache_folder();

// The process-wide settings (`--no-mesh-cache` and CCM_MESH_CACHE=off turn the cache off).
MeshCacheSettings mesh_cache_settings();
void set_mesh_cache_settings(const MeshCacheSettings& settings);

// What the cache did on the calling thread: meshes read back, meshes made (and filed), and the
// seconds each took. Per thread, so that runs side by side (`ccm rig calibrate --jobs`), each
// building its model on its own thread, count their own meshes.
struct MeshCacheStats {
  long hits = 0, misses = 0;
  double read_seconds = 0.0, mesh_seconds = 0.0;
};
MeshCacheStats mesh_cache_stats();

// The mesh filed under `key`, or `make()`'s (then filed). With the cache off, `make()`.
TetMesh cached_mesh(const std::string& key, const std::function<TetMesh()>& make);

// A mesh as bytes and back (the cache's file body); read_mesh_bytes returns false on anything
// that is not a whole mesh.
std::string mesh_bytes(const TetMesh& mesh);
bool read_mesh_bytes(const std::string& bytes, TetMesh& mesh);

}  // namespace ccm
