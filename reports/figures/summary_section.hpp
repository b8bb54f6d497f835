// The report's first section: the answer. The decision rule (study/recommend/decision_rule.hpp)
// in one sentence, a few sentences generated from the measured points, the recommendation maps
// at the chosen max error, the per-point table (final-state errors, measured cost ratio RTR,
// w, the rule on the measured values and on the fitted surfaces, the consistency flag; written
// as points.csv) and the modelling choices the answers rest on.
#pragma once

#include <string>
#include <vector>

#include "reports/data/report_data.hpp"
#include "reports/figures/report_content.hpp"

namespace ccm::reports {

// One row per grid point (main grid, unusable ones with their reason), in index order.
Table points_table(const ReportData& data, double max_error);

// The generated sentences: per axis group, how many points get rigid, over which ER, where CCM
// is cheaper, and how many fitted answers differ from the measured ones or are unreliable.
std::vector<std::string> summary_sentences(const ReportData& data, double max_error);

Section summary_section(const ReportData& data, double max_error);

}  // namespace ccm::reports
