// What one simulation of a grid point produced: the artifact's sampled histories, the timing
// figures of the normalised runtime (thesis eq. 2.40-2.43) and the stability verdict.
// Produced by the point runner, consumed by the metrics and the store.
#pragma once

#include <string>
#include <vector>

#include "study/grid/grid_point.hpp"

namespace ccm::study {

// Artifact histories at the output sample times (both models of a point share the times).
struct ArtifactHistory {
  std::vector<double> time;            // [s]
  std::vector<double> u_mean;          // mean nodal displacement magnitude [m]
  std::vector<double> u_max;           // max nodal displacement magnitude [m]
  std::vector<double> kinetic_energy;  // artifact kinetic energy [J]
};

struct RunRecord {
  GridPoint point;
  ImpactModel model = ImpactModel::ccm;
  std::string verdict;         // "completed" or "unstable"
  std::string reason;          // empty when completed
  double unstable_time = 0.0;  // [s], when unstable
  long steps = 0;
  double wall_seconds = 0.0;               // whole run, set-up excluded
  double initial_stable_dt = 0.0;          // ISTS [s]                        (eq. 2.42)
  double average_iteration_seconds = 0.0;  // AIR = wall / steps [s]      (eq. 2.41)
  double dt_min = 0.0, dt_max = 0.0;       // [s]
  double max_energy_error = 0.0;           // largest relative energy-balance error seen
  long n_elements = 0, n_nodes = 0;
  std::string scene_hash;            // content hash of the scene text that was run
  std::string started_at, ended_at;  // ISO 8601 UTC
  ArtifactHistory artifact;

  bool completed() const { return verdict == "completed"; }
};

}  // namespace ccm::study
