// The tables `ccm study run` prints at the end: every point's verdicts, final-state errors,
// measured cost ratio and the decision rule's answer; and the convergence runs' accuracy against
// runtime.
#pragma once

#include <cstdio>
#include <vector>

#include "records/point_metrics.hpp"
#include "records/run_record.hpp"
#include "study/fit/study_fits.hpp"
#include "study/grid/grid_spec.hpp"
#include "study/metrics/convergence.hpp"
#include "study/metrics/thesis_trends.hpp"
#include "study/recommend/decision_rule.hpp"

namespace ccm {

// Per point: the errors, the measured cost ratio, w, the decision rule's answer on the
// measured values and on the fitted surfaces, and a flag where the two disagree or the fitted
// answer is unreliable (study/recommend/recommendation.hpp decide_grid_points).
void print_point_table(std::FILE* out, const std::vector<study::PointMetrics>& points,
                       const study::StudyFits& fits, double max_error = study::kDefaultMaxError);
void print_convergence_table(std::FILE* out, const std::vector<study::ConvergenceRow>& rows);
// The thesis's trends per point (study/metrics/thesis_trends.hpp), with the point's RTR.
void print_trend_table(std::FILE* out, const std::vector<study::TrendRow>& trends,
                       const std::vector<study::PointMetrics>& points);

}  // namespace ccm
