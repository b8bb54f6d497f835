// Writes a report folder: index.html, every figure as <id>.svg and every table as <id>.csv.
// The folder is built beside the target under a temporary name and then swapped in, so a
// re-run replaces the old report whole and a failed run leaves the old one untouched.
#pragma once

#include <filesystem>

#include "reports/data/report_data.hpp"
#include "reports/figures/provenance_section.hpp"
#include "reports/figures/report_content.hpp"
#include "study/recommend/decision_rule.hpp"

namespace ccm::reports {

struct ReportOptions {
  double max_error = study::kDefaultMaxError;  // the decision rule's error threshold
};

// Every section of the report, in page order, with the figures' plots but no SVG yet (no
// gnuplot needed).
ReportContent plan_report(const ReportData& data, const ReportOptions& options,
                          const ReportStamp& stamp);

// plan_report with every figure rendered. Throws ReportError when gnuplot is missing or fails.
ReportContent build_report(const ReportData& data, const ReportOptions& options,
                           const ReportStamp& stamp);

// Writes `content` into `out_dir` (created, or replaced whole). Throws ReportError naming the
// path when it cannot.
void write_report(const ReportContent& content, const std::filesystem::path& out_dir);

}  // namespace ccm::reports
