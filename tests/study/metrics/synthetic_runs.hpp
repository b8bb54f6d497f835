// Two hand-made runs of one grid point with short histories whose metrics are worked out by
// hand in test_point_metrics.cpp (shared with the store tests).
#pragma once

#include "study/runner/run_record.hpp"

namespace ccm::test {

inline study::RunRecord synthetic_run(study::ImpactModel model, int point_index = 7) {
  study::RunRecord run;
  run.point.index = point_index;
  run.point.modulus_ratio = 100.0;
  run.point.length_ratio = 1.0;
  run.point.kinetic_energy = 50.0;
  run.point.other_axes["nu"] = 0.49;
  run.model = model;
  run.verdict = "completed";
  run.artifact.time = {0.0, 0.05, 0.10, 0.15};
  if (model == study::ImpactModel::ccm) {
    run.artifact.u_mean = {0.0, 1.0, 2.0, 2.0};
    run.artifact.u_max = {0.0, 2.0, 4.0, 3.0};
    run.artifact.kinetic_energy = {0.0, 4.0, 2.0, 1.0};
    run.average_iteration_seconds = 4e-3;
    run.initial_stable_dt = 1e-6;
    run.steps = 150000;
  } else {
    run.artifact.u_mean = {0.0, 1.0, 3.0, 4.0};
    run.artifact.u_max = {0.0, 2.0, 5.0, 6.0};
    run.artifact.kinetic_energy = {0.0, 4.0, 4.0, 4.0};
    run.average_iteration_seconds = 1e-3;
    run.initial_stable_dt = 2e-6;
    run.steps = 75000;
  }
  run.wall_seconds = run.average_iteration_seconds * static_cast<double>(run.steps);
  run.dt_min = 0.5 * run.initial_stable_dt;
  run.dt_max = run.initial_stable_dt;
  run.max_energy_error = 1e-3;
  run.n_elements = 1234;
  run.n_nodes = 321;
  run.scene_hash = "0123456789abcdef";
  run.started_at = "2026-11-22T05:00:00.000Z";
  run.ended_at = "2026-11-22T05:01:00.000Z";
  return run;
}

}  // namespace ccm::test
