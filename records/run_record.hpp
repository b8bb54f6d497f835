// What one simulation of a grid point produced: the artifact's sampled histories, the timing
// figures of the normalised runtime (thesis eq. 2.40-2.43) and the stability verdict.
// Produced by the point runner, consumed by the metrics and the store.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "records/grid_point.hpp"

namespace ccm::study {

// Artifact histories at the output sample times (both models of a point share the times).
struct ArtifactHistory {
  std::vector<double> time;            // [s]
  std::vector<double> u_mean;          // mean nodal displacement magnitude [m]
  std::vector<double> u_max;           // max nodal displacement magnitude [m]
  std::vector<double> kinetic_energy;  // artifact kinetic energy [J]
};

// The impactor's centre-of-mass velocity at the same sample times, and its mass: what the
// designer's metrics read (force from the momentum it exchanges, contact duration, rebound;
// study/metrics/impact_metrics.hpp). Empty for a run stored before ccm kept it.
struct ImpactorHistory {
  double mass = 0.0;               // [kg]
  std::vector<double> vx, vy, vz;  // [m/s]
  bool empty() const { return vx.empty(); }
};

// What the step loop of a run cost and what set its steps (RunSummary, explicit_integrator.hpp).
// The measured cost TR of the trade study is step_cpu_seconds (docs/store.md).
struct MeasuredCost {
  double step_cpu_seconds = 0.0;   // thread CPU time of the step loop [s] (set-up excluded)
  double step_wall_seconds = 0.0;  // wall time of the step loop [s]
  double dt_first = 0.0;           // the first step actually taken [s]
  double dt_mean = 0.0;            // time reached / steps [s]
  // Steps by what set their length; the four sum to RunRecord::steps.
  long steps_structure = 0, steps_contact = 0, steps_max_dt = 0, steps_landing = 0;
  std::optional<double> dt_contact_min;  // smallest contact-limited step [s]; none: no such step
};

struct RunRecord {
  GridPoint point;
  ImpactModel model = ImpactModel::ccm;
  std::string verdict;         // "completed" or "unstable"
  std::string reason;          // empty when completed
  double unstable_time = 0.0;  // [s], when unstable
  long steps = 0;
  double wall_seconds = 0.0;               // whole run, meshing excluded
  double initial_stable_dt = 0.0;          // ISTS: the structural step at t = 0 [s]  (eq. 2.42)
  double average_iteration_seconds = 0.0;  // AIR = step CPU seconds / steps [s]  (eq. 2.41)
  // Empty for a run stored before ccm measured it (store schema < 4): its cost is unknown.
  std::optional<MeasuredCost> cost;
  // The point index of the run this record was copied from (same model, same scene text), or
  // none when this run was simulated itself (study run reuse, docs/store.md).
  std::optional<int> reuses_point;
  double dt_min = 0.0, dt_max = 0.0;  // [s]
  double max_energy_error = 0.0;      // largest relative energy-balance error seen
  long n_elements = 0, n_nodes = 0;
  std::string scene_hash;            // content hash of the scene text that was run
  std::string started_at, ended_at;  // ISO 8601 UTC
  ArtifactHistory artifact;
  ImpactorHistory impactor;

  bool completed() const { return verdict == "completed"; }
};

}  // namespace ccm::study
