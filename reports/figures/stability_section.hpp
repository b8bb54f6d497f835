// The stability table: every run's verdict and reason, its time-step range and its largest
// energy-balance error, and the status of runs that failed or never finished.
#pragma once

#include "reports/data/report_data.hpp"
#include "reports/figures/report_content.hpp"

namespace ccm::reports {

Table stability_table(const ReportData& data);
Section stability_section(const ReportData& data);

}  // namespace ccm::reports
