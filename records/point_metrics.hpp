// Everything the trade study derives from the two runs of one grid point (thesis 2.8):
// cumulative and final-state errors, normalised runtimes, runtime ratio and weighting functions.
#pragma once

#include <algorithm>
#include <optional>
#include <string>

#include "records/grid_point.hpp"
#include "records/run_record.hpp"

namespace ccm::study {

// One value per artifact quantity compared.
struct ArtifactErrors {
  double u_mean = 0.0;          // mean nodal displacement magnitude
  double u_max = 0.0;           // max nodal displacement magnitude
  double kinetic_energy = 0.0;  // artifact kinetic energy
};

// The designer's quantities of one run (study/metrics/impact_metrics.hpp, IM.1-IM.4).
struct ImpactQuantities {
  double peak_force = 0.0;        // [N]
  double indentation = 0.0;       // [m]
  double contact_duration = 0.0;  // [s]
  double rebound_speed = 0.0;     // [m/s]
  double approach_speed = 0.0;    // [m/s]
};

// The rigid run's error against the CCM run in each (IM.5), in [0, 1].
struct ImpactErrors {
  double peak_force = 0.0, indentation = 0.0, contact_duration = 0.0, rebound_speed = 0.0;
  double worst() const {
    return std::max({peak_force, indentation, contact_duration, rebound_speed});
  }
};

// Timing of one model's run.
struct ModelTiming {
  std::string verdict;  // "completed" or "unstable"
  long steps = 0;
  double wall_seconds = 0.0;               // measured, whole run
  double average_iteration_seconds = 0.0;  // AIR (eq. 2.41)
  double initial_stable_dt = 0.0;          // ISTS (eq. 2.42): the structural step at t = 0
  double normalised_runtime = 0.0;         // NT = AIR / ISTS [s/s]; 0 when not usable
  // TR: the CPU seconds the run's step loop took (measured); 0 when not usable.
  double total_runtime = 0.0;
  // The thesis's estimate TR = t_f NT (eq. 2.43); 0 when not usable.
  double total_runtime_thesis_estimate = 0.0;
};

struct PointMetrics {
  GridPoint point;
  ModelTiming ccm, rigid;
  // False when either run went unstable, has no measured cost (stored before schema 4) or its
  // histories cannot be compared: the point is kept in the store with the reason, and left out
  // of every fit.
  bool usable = false;
  std::string excluded_reason;
  double t_final = 0.0;        // last common sample time [s]
  ArtifactErrors cumulative;   // eqs. 2.34-2.36
  ArtifactErrors final_state;  // eqs. 2.37-2.39
  // RTR = TR_CCM / TR_rigid with the measured TR (eq. 2.40 with the time actually spent
  // stepping): what every decision and weighting function uses.
  double runtime_ratio = 0.0;
  // The thesis's estimate NT_CCM / NT_rigid with NT = AIR / ISTS (eqs. 2.40-2.42): shown beside
  // the measured ratio, never used for a decision.
  double runtime_ratio_thesis_estimate = 0.0;
  ArtifactErrors weighting;  // w = final-state error / RTR, measured RTR (thesis 2.8, App. B)
  // The designer's metrics: each run's quantities and the rigid run's errors; none when either
  // run kept no impactor history (stored before ccm did) or the point is not usable.
  std::optional<ImpactQuantities> ccm_impact, rigid_impact;
  std::optional<ImpactErrors> impact_errors;
};

// Derives the metrics of one point from its CCM and rigid runs. The runs must belong to the
// same grid point and share their sample times (relative tolerance 1e-9 of t_final); an
// unstable run, or one without a measured cost, gives an unusable point with the reason, never an
// exception. Throws
// std::invalid_argument when the records are not the two models of one point, or when a
// completed run lacks a positive AIR or ISTS.
}  // namespace ccm::study
