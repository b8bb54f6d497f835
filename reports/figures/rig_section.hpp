// The report's benchtop rig section (thesis chapter 3): per stored rig run its channel figures
// (rig_channel_figures.hpp), the metrics, runs and calibration tables (rig_tables.hpp); a store
// without a rig run says so and how to add one.
#pragma once

#include "reports/data/report_data.hpp"
#include "reports/figures/report_content.hpp"

namespace ccm::reports {

inline constexpr const char* kNoRigRunText =
    "No benchtop rig run is stored in this database; run `ccm rig run CASE --data DIR --db "
    "FILE` to add one.";

Section rig_section(const RigReportData& rig);

}  // namespace ccm::reports
