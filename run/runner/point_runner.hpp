// Runs one model of one grid point in-process (mesh, run, sample) and returns its RunRecord.
#pragma once

#include <functional>
#include <optional>

#include "engine/solver/explicit_integrator.hpp"
#include "records/grid_point.hpp"
#include "records/run_record.hpp"
#include "study/grid/grid_spec.hpp"

namespace ccm::study {

// Called about every `progress_seconds` of wall time during the run (simulated time, steps,
// dt, wall time of this run), for a progress line or an ETA over the whole grid.
using PointProgressFn = std::function<void(const GridPoint&, ImpactModel, const Progress&)>;

// How a run of a whole-impact study ends (its scene ends one hold after separation; app's
// study_runs.hpp runs a point's two runs together): not before `earliest` (the partner's end),
// or, with `fixed`, at that time without the separation criterion (the partner ended later; up
// to its first end the run is the same, bit for bit).
struct PointEnd {
  double earliest = 0.0;        // [s]
  std::optional<double> fixed;  // [s]
};

struct PointRunOptions {
  PointProgressFn progress;  // optional
  double progress_seconds = 0.5;
  PointEnd end;
};

// Builds the point's scene (run/scene/point_scene.hpp), meshes it, runs it to t_f or to an
// instability and records the artifact histories at the output times. An unstable run is a
// record with verdict "unstable", not an error. Throws ccm::ConfigError when the scene cannot be
// built (e.g. a mesh size Gmsh rejects), naming the point's scene.
RunRecord run_point(const GridSpec& spec, const GridPoint& point, ImpactModel model,
                    const PointRunOptions& options = {});

}  // namespace ccm::study
