#include "reports/write/report_writer.hpp"

#include <fstream>

#include "reports/figures/comparison_section.hpp"
#include "reports/figures/validation_section.hpp"
#include "reports/figures/error_runtime_section.hpp"
#include "reports/figures/fit_section.hpp"
#include "reports/figures/rig_section.hpp"
#include "reports/figures/stability_section.hpp"
#include "reports/figures/summary_section.hpp"
#include "reports/figures/trade_study_section.hpp"
#include "reports/html/html_page.hpp"
#include "reports/report_error.hpp"
#include "reports/write/folder_swap.hpp"

namespace ccm::reports {
namespace {

namespace fs = std::filesystem;

void write_text(const fs::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
  out.close();
  if (!out) throw ReportError(file.string() + ": cannot write");
}

}  // namespace

ReportContent plan_report(const ReportData& data, const ReportOptions& options,
                          const ReportStamp& stamp) {
  ReportContent content{.title = "ccm trade study report: " + data.provenance.study_name};
  content.sections.push_back(summary_section(data, options.max_error));  // the answer first
  content.sections.push_back(trade_study_section(data));
  content.sections.push_back(stability_section(data));
  content.sections.push_back(fit_section(data));
  content.sections.push_back(error_runtime_section(data));
  content.sections.push_back(rig_section(data.rig));
  content.sections.push_back(comparison_section(data.comparisons));
  content.sections.push_back(validation_section(data.validations));
  content.sections.push_back(provenance_section(data, stamp));
  return content;
}

ReportContent build_report(const ReportData& data, const ReportOptions& options,
                           const ReportStamp& stamp) {
  ReportContent content = plan_report(data, options, stamp);
  render_figures(content);
  return content;
}

void write_report(const ReportContent& content, const fs::path& out_dir) {
  const fs::path staging = make_staging_folder(out_dir);
  try {
    for (const Section& s : content.sections) {
      for (const Figure& f : s.figures) write_text(staging / (f.id + ".svg"), f.svg);
      for (const Table& t : s.tables) write_text(staging / (t.id + ".csv"), to_csv(t));
    }
    write_text(staging / "index.html", html_page(content));
    swap_in_folder(staging, out_dir);
  } catch (...) {
    std::error_code ignored;
    fs::remove_all(staging, ignored);
    throw;
  }
}

}  // namespace ccm::reports
