// Runs one model of one grid point in-process (mesh, run, sample) and returns its RunRecord.
#pragma once

#include <functional>

#include "engine/solver/explicit_integrator.hpp"
#include "records/grid_point.hpp"
#include "records/run_record.hpp"
#include "study/grid/grid_spec.hpp"

namespace ccm::study {

// Called about every `progress_seconds` of wall time during the run (simulated time, steps,
// dt, wall time of this run), for a progress line or an ETA over the whole grid.
using PointProgressFn = std::function<void(const GridPoint&, ImpactModel, const Progress&)>;

struct PointRunOptions {
  PointProgressFn progress;  // optional
  double progress_seconds = 0.5;
};

// Builds the point's scene (run/scene/point_scene.hpp), meshes it, runs it to t_f or to an
// instability and records the artifact histories at the output times. An unstable run is a
// record with verdict "unstable", not an error. Throws ccm::ConfigError when the scene cannot be
// built (e.g. a mesh size Gmsh rejects), naming the point's scene.
RunRecord run_point(const GridSpec& spec, const GridPoint& point, ImpactModel model,
                    const PointRunOptions& options = {});

}  // namespace ccm::study
