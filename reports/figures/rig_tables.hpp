// The benchtop rig's tables: the comparison metrics per case and channel (mean over the
// trials), the rig runs shown (size, steps, time-step range, wall time, energy balance,
// verdict) and the calibrations (each parameter before and after, the objective).
#pragma once

#include "reports/data/report_data.hpp"
#include "reports/tables/table.hpp"

namespace ccm::reports {

Table rig_metrics_table(const RigReportData& rig);      // id rig-metrics
Table rig_runs_table(const RigReportData& rig);         // id rig-runs
Table rig_calibration_table(const RigReportData& rig);  // id rig-calibrations
Table rig_prediction_table(const RigReportData& rig);   // id rig-left-out

}  // namespace ccm::reports
