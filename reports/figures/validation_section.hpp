// The report's "Your bench tests" section: every `ccm validate` recorded in the store
// (db/store/validation_store.hpp): per validation, the rating table (each channel against each
// trial and the trials' mean: nRMSE, peak error, time-of-peak error, the ISO/TS 18571 sub-scores,
// rating and grade; trials a fit left out marked) and one figure per channel, the simulation
// against the trials' mean with their spread as a band.
#pragma once

#include <vector>

#include "db/store/validation_store.hpp"
#include "reports/figures/report_content.hpp"

namespace ccm::reports {

Section validation_section(const std::vector<db::ValidationRow>& validations);

}  // namespace ccm::reports
