// The trade-study section (thesis 2.8): runtime, iteration time and stable step per point
// (Figs. 2-16..2-18), artifact kinetic-energy histories at the corner points (2-19),
// cumulative and final-state errors (2-22..2-27) and normalised runtimes with their fitted
// surfaces (2-28, reports/figures/normalised_runtime_figures.hpp).
#pragma once

#include "reports/data/report_data.hpp"
#include "reports/figures/report_content.hpp"

namespace ccm::reports {

Section trade_study_section(const ReportData& data);

// The corner points of the main grid: lowest and highest ER by lowest and highest RLS, at the
// highest KE (thesis Fig. 2-19 compares ER 1e6 and 1e0 at RLS 0.5, KE 100 J).
std::vector<study::GridPoint> corner_points(const std::vector<study::GridPoint>& grid);

}  // namespace ccm::reports
