// Two hand-made runs of one grid point with short histories whose metrics are worked out by
// hand in test_point_metrics.cpp (shared with the store tests).
#pragma once

#include <algorithm>

#include "records/run_record.hpp"

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
    run.impactor.vz = {-2.0, -1.0, 0.5, 0.5};  // 10 kg: 200 N, then 300 N, then free
    run.average_iteration_seconds = 4e-3;
    run.initial_stable_dt = 1e-6;
    run.steps = 150000;
  } else {
    run.artifact.u_mean = {0.0, 1.0, 3.0, 4.0};
    run.artifact.u_max = {0.0, 2.0, 5.0, 6.0};
    run.artifact.kinetic_energy = {0.0, 4.0, 4.0, 4.0};
    run.impactor.vz = {-2.0, 0.0, 1.0, 1.0};  // 400 N, then 200 N, then free
    run.average_iteration_seconds = 1e-3;
    run.initial_stable_dt = 2e-6;
    // Contact-limited: 4 x the t_f / ISTS = 75000 steps the thesis's estimate assumes.
    run.steps = 300000;
  }
  run.impactor.mass = 10.0;
  run.impactor.vx.assign(4, 0.0);
  run.impactor.vy.assign(4, 0.0);
  run.wall_seconds = run.average_iteration_seconds * static_cast<double>(run.steps);
  run.dt_max = run.initial_stable_dt;
  study::MeasuredCost cost;
  cost.step_cpu_seconds = run.wall_seconds;  // ccm 600 s, rigid 300 s
  cost.step_wall_seconds = 1.25 * run.wall_seconds;
  cost.dt_first = run.initial_stable_dt;
  cost.dt_mean = 0.15 / static_cast<double>(run.steps);
  cost.steps_landing = 150;
  cost.steps_structure = model == study::ImpactModel::ccm ? run.steps - 150 : 50000;
  cost.steps_contact = run.steps - cost.steps_landing - cost.steps_structure;
  if (cost.steps_contact > 0) cost.dt_contact_min = 0.25 * run.initial_stable_dt;
  run.cost = cost;
  run.dt_min = 0.5 * std::min(cost.dt_mean, run.initial_stable_dt);
  run.max_energy_error = 1e-3;
  run.n_elements = 1234;
  run.n_nodes = 321;
  run.scene_hash = "0123456789abcdef";
  run.started_at = "2026-11-22T05:00:00.000Z";
  run.ended_at = "2026-11-22T05:01:00.000Z";
  return run;
}

}  // namespace ccm::test
