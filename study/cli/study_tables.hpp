// The tables `ccm study run` prints at the end: every point's verdicts, final-state errors,
// runtime ratio and recommended model; and the convergence runs' accuracy against runtime.
#pragma once

#include <cstdio>
#include <vector>

#include "study/fit/study_fits.hpp"
#include "study/grid/grid_spec.hpp"
#include "study/metrics/point_metrics.hpp"
#include "study/runner/run_record.hpp"

namespace ccm {

// One convergence run compared with the finest CCM run of its point (thesis 2.8 "report error
// against run time"): final-state errors (eqs. 2.37-2.39) and the run's wall time.
struct ConvergenceRow {
  study::GridPoint point;  // other_axes["mesh_scale"] is the resolution factor
  study::ImpactModel model = study::ImpactModel::ccm;
  bool reference = false;  // this is the finest CCM run itself
  bool usable = false;     // both this run and the reference completed
  study::ArtifactErrors final_state;
  double wall_seconds = 0.0;
  long n_elements = 0;
};

// Groups the runs by (ER, RLS, KE) and compares each with the group's finest completed CCM run.
std::vector<ConvergenceRow> compare_convergence_runs(const std::vector<study::RunRecord>& runs);

void print_point_table(std::FILE* out, const std::vector<study::PointMetrics>& points,
                       const study::StudyFits& fits);
void print_convergence_table(std::FILE* out, const std::vector<ConvergenceRow>& rows);

}  // namespace ccm
