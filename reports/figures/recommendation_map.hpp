// The recommendation map: for each studied KE level, the (ER, RLS) plane coloured by the model
// `study::recommend` chooses at a user-chosen error threshold (thesis 2.8, App. B).
#pragma once

#include "reports/data/report_data.hpp"
#include "reports/figures/report_content.hpp"

namespace ccm::reports {

// Map resolution per axis: cells evaluated over the fitted range of log10 ER and RLS.
inline constexpr int kMapCells = 31;

Section recommendation_section(const ReportData& data, double max_error);

}  // namespace ccm::reports
