#include "app/setup_time.hpp"

#include <fmt/format.h>

namespace ccm {

std::string setup_time_text(double setup_seconds, const MeshCacheStats& m) {
  return fmt::format(
      "{:.3g} s: meshing {:.3g} s ({} meshed), reading {:.3g} s ({} from the mesh cache{}), the "
      "rest {:.3g} s (masses, surfaces, contact)",
      setup_seconds, m.mesh_seconds, m.misses, m.read_seconds, m.hits,
      mesh_cache_settings().enabled ? "" : ": off",
      setup_seconds - m.mesh_seconds - m.read_seconds);
}

MeshCacheStats mesh_cache_delta(const MeshCacheStats& before, const MeshCacheStats& after) {
  return {after.hits - before.hits, after.misses - before.misses,
          after.read_seconds - before.read_seconds, after.mesh_seconds - before.mesh_seconds};
}

}  // namespace ccm
