#include "tests/reports/synthetic_rig.hpp"

#include <vector>

#include "tests/support/rig_comparison.hpp"

namespace ccm::test {
namespace {

rig::MeasuredTrial trial(int n, double scale) {
  rig::MeasuredTrial m;
  m.case_code = "RX025";
  m.trial = n;
  for (int k = 0; k <= 20; ++k) {
    const double t = 0.01 * k;
    m.impactor_velocity_mps.t.push_back(t);
    m.impactor_velocity_mps.value.push_back(scale * t);
    m.artifact_angle_deg.t.push_back(t);
    m.artifact_angle_deg.value.push_back(scale * t * t);
    m.pressure_kpa.t.push_back(t);
    m.pressure_kpa.value.push_back(k >= 5 && k <= 10 ? 10.0 * scale : 0.0);
  }
  return m;
}

}  // namespace

db::RigRunRecord synthetic_rig_record() {
  const std::vector<rig::MeasuredTrial> trials{trial(1, 1.0), trial(2, 1.1), trial(3, 0.9)};
  rig::RigChannels sim{trials[0].impactor_velocity_mps, trials[0].artifact_angle_deg,
                       trials[0].pressure_kpa};
  for (double& v : sim.pressure_kpa.value) v *= 1.5;
  db::RigRunRecord r;
  r.row.case_code = "RX025";
  r.row.drive = "open-loop";
  r.row.drive_trial = 2;
  r.row.parameters = "pin=exact";
  r.row.status = "completed";
  r.row.window_end = 0.2;
  r.row.n_elements = 3121;
  r.row.n_nodes = 1200;
  r.row.steps = 1000;
  r.row.dt_initial = 5e-7;
  r.row.dt_min = 4e-7;
  r.row.dt_max = 6e-7;
  r.row.wall_seconds = 1.5;
  r.row.max_energy_error = 0.012;
  r.row.cases_hash = "cases0123456789ab";
  r.row.geometry_hash = "geometry01234567";
  r.row.started_at = r.row.ended_at = "2026-01-01T00:00:00.000Z";
  for (const rig::MeasuredTrial& m : trials) {
    r.trials.push_back(m.trial);
    r.measured_channels.push_back({m.impactor_velocity_mps, m.artifact_angle_deg, m.pressure_kpa});
  }
  r.comparison = test::rig_comparison(trials, sim);
  r.measured = rig::measured_spread(trials, 1.0);
  r.channels = sim;
  return r;
}

long long write_synthetic_rig(const std::filesystem::path& file) {
  db::RigStore store(file);
  db::RigRunRecord r = synthetic_rig_record();
  const long long id = store.record_run(r);
  r.row.purpose = "calibration";
  r.row.objective = 0.4;
  const long long before = store.record_run(r);
  r.row.objective = 0.25;
  const long long after = store.record_run(r);
  db::RigCalibrationRecord k;
  k.case_code = "RX025";
  k.drive = "open-loop";
  k.algorithm = "bobyqa";
  k.objective_name = "mean nRMSE";
  k.result = "converged";
  k.evaluations = 12;
  k.max_evaluations = 40;
  k.before_run_id = before;
  k.after_run_id = after;
  k.objective_before = 0.4;
  k.objective_after = 0.25;
  k.parameters = {{"pin_damping", 0.0, 2.0, 0.5, 1.25, 0.08, 0.25}};
  r.row.case_code = "RX050";
  r.row.objective = 0.5;
  const long long left_out_start = store.record_run(r);
  r.row.objective = 0.3;
  const long long left_out_calibrated = store.record_run(r);
  k.predictions = {{"RX050", left_out_start, left_out_calibrated, 0.5, 0.3}};
  k.trials = {{1, true, 0.4, 0.25}, {3, false, 0.45, 0.35}};  // fitted on trial 1
  k.history = {{"pin_damping=0.5", 0.4, "completed", 1.0},
               {"pin_damping=1.25", 0.25, "completed", 1.0}};
  k.started_at = k.ended_at = "2026-01-01T00:00:00.000Z";
  store.record_calibration(k);
  return id;
}

}  // namespace ccm::test
