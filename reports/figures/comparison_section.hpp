// The report's "Your designs compared" section: every `ccm compare` recorded in the store
// (db/store/comparison_store.hpp), its measured answer and the study's prediction beside it.
#pragma once

#include <vector>

#include "db/store/comparison_store.hpp"
#include "reports/figures/report_content.hpp"

namespace ccm::reports {

Section comparison_section(const std::vector<db::ComparisonRow>& comparisons);

}  // namespace ccm::reports
