// The thesis's three trade-study trends (section 2.8, Fig. 2-16 to 2-21), measured on a grid
// point from its two runs:
//   - at high ER the two models' artifact kinetic energy agrees over the run (Fig. 2-19):
//       ke_gap = max_i |KE_c,i - KE_r,i| / max_i KE_r,i       (largest gap over the run, as a
//       fraction of the rigid model's peak; the thesis's "within 15 %" reading);
//   - at ER = 1 the CCM artifact takes less kinetic energy and deforms less (Fig. 2-19 to
//     2-21; the thesis: 59.2 %, 35.2 % and 39.1 % lower at RLS 0.5, KE 100 J):
//       ke_ratio = KE_c(t_f) / KE_r(t_f), u_mean_ratio and u_max_ratio likewise;
//   - RTR grows with ER (Fig. 2-16): the point's RTR (eq. 2.40), from its PointMetrics.
#pragma once

#include <vector>

#include "records/grid_point.hpp"
#include "records/run_record.hpp"

namespace ccm::study {

struct TrendRow {
  GridPoint point;
  double ke_gap = 0.0;
  double ke_ratio = 0.0;
  double u_mean_ratio = 0.0;
  double u_max_ratio = 0.0;
};

// Throws std::invalid_argument when the runs' histories have different lengths or are empty, or
// when the rigid run's artifact never moves (no peak to normalise by).
TrendRow thesis_trend(const RunRecord& ccm, const RunRecord& rigid);

}  // namespace ccm::study
