// The convergence mode (grid [convergence] table): every run of a convergence point compared
// with the finest completed CCM run of its (ER, RLS, KE) (thesis 2.8 "report error against run
// time"): final-state errors (eqs. 2.37-2.39), wall time, accuracy per second. Shared by the
// table `ccm study run` prints and by `ccm report`.
#pragma once

#include <vector>

#include "records/grid_point.hpp"
#include "records/point_metrics.hpp"
#include "records/run_record.hpp"

namespace ccm::study {

struct ConvergenceRow {
  GridPoint point;  // other_axes["mesh_scale"] is the resolution factor
  ImpactModel model = ImpactModel::ccm;
  bool reference = false;  // this is the finest CCM run itself
  bool usable = false;     // both this run and the reference completed, on the same sample times
  ArtifactErrors final_state{};  // against the reference; zero for the reference itself
  double wall_seconds = 0.0;
  long n_elements = 0;
};

// The mesh scale of a point: other_axes["mesh_scale"], 1 when absent.
double mesh_scale(const GridPoint& point);

// Groups the runs by (ER, RLS, KE) and compares each with the group's finest (smallest mesh
// scale) completed CCM run; one row per run, in the order given.
std::vector<ConvergenceRow> compare_convergence_runs(const std::vector<RunRecord>& runs);

// Accuracy per second of a usable row: (1 - final-state KE error) / wall time [1/s]; NaN when
// the wall time is not positive.
double accuracy_per_second(const ConvergenceRow& row);

}  // namespace ccm::study
