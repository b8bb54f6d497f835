// Weighting functions and runtime ratio with their fitted surfaces and equations (thesis
// Fig. 2-29, Appendix B), and the table of every fit of the study.
#pragma once

#include "reports/data/report_data.hpp"
#include "reports/figures/report_content.hpp"

namespace ccm::reports {

Section fit_section(const ReportData& data);

// Every stored fit (metric, KE, degrees, equation, R^2, LOO RMSE, points), then the points and
// (metric, KE) pairs left out, with the reason.
Table fits_table(const study::StudyFits& fits);

}  // namespace ccm::reports
