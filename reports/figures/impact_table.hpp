// The designer's metrics of each grid point (docs/metrics.md, IM.1-IM.5): each run's peak
// contact force, deepest indentation, contact duration and rebound speed, the rigid run's error
// in each, beside the rule's final-state errors (they do not decide); written as impact.csv.
#pragma once

#include <optional>
#include <string>

#include "reports/data/report_data.hpp"
#include "reports/figures/report_content.hpp"

namespace ccm::reports {

// One row per grid point that has them, in index order; none when no point has them (a study
// stored before ccm kept the impactor's history).
std::optional<Table> impact_table(const ReportData& data);

// How many of those points the rigid model matches within max_error on all four, and which
// metric is most often the worst: one sentence, or none with the table.
std::optional<std::string> impact_sentence(const ReportData& data, double max_error);

}  // namespace ccm::reports
