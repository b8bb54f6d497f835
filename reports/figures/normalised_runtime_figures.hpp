// Normalised runtime NT = AIR / ISTS of both models over (log10 ER, RLS), one figure per KE
// level, each with its fitted surface (stored by `ccm study run` as the fits log10_nt_ccm and
// log10_nt_rigid: fitted to log10 NT, drawn as NT), the data points, and the equations in the
// caption (thesis Fig. 2-28).
#pragma once

#include <vector>

#include "reports/data/report_data.hpp"
#include "reports/figures/report_content.hpp"

namespace ccm::reports {

std::vector<Figure> normalised_runtime_figures(const ReportData& data);

}  // namespace ccm::reports
