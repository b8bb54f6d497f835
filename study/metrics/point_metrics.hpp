// The metrics of one grid point from its two runs (thesis 2.8, eqs. 2.34-2.43; docs/metrics.md).
#pragma once

#include "records/point_metrics.hpp"
#include "records/run_record.hpp"

namespace ccm::study {

PointMetrics compute_point_metrics(const RunRecord& ccm, const RunRecord& rigid);

}  // namespace ccm::study
