// Where a run's set-up time went, as `ccm run` and `ccm rig run` print it and write it into
// summary.toml: "1.23 s: meshing 1.1 s (2 meshed), reading 0.02 s (1 from the mesh cache), the
// rest 0.11 s (masses, surfaces, contact)".
#pragma once

#include <string>

#include "engine/mesh/mesh_cache.hpp"

namespace ccm {

// `meshing`: what the mesh cache did during the set-up (the difference of two mesh_cache_stats).
std::string setup_time_text(double setup_seconds, const MeshCacheStats& meshing);

// The mesh cache's counters from `before` to `after`.
MeshCacheStats mesh_cache_delta(const MeshCacheStats& before, const MeshCacheStats& after);

}  // namespace ccm
