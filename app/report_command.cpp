// `ccm report --db FILE --out DIR [--max-error E]`: the study's self-contained HTML report.
#include <fmt/format.h>

#include <cmath>

#include "app/command_errors.hpp"
#include "app/output_file.hpp"
#include "app/run_command.hpp"
#include "app/study_commands.hpp"
#include "app/study_store_open.hpp"
#include "reports/data/report_loader.hpp"
#include "reports/report_error.hpp"
#include "reports/write/report_writer.hpp"

namespace ccm {
namespace {

reports::ReportData load_study(const std::filesystem::path& file) {
  auto store = open_study_store(file);
  reports::ReportData data = reports::load_report_data(*store);
  if (data.status.empty())
    throw StudyInputError(file.string() + ": study \"" + data.provenance.study_name +
                          "\" has no grid points yet (an empty study): run `ccm study run` "
                          "first");
  if (data.runs.empty()) {
    long failed = 0;
    for (const db::PointStatus& s : data.status)
      for (const auto& run : {s.ccm, s.rigid}) failed += run == db::RunStatus::failed;
    throw StudyInputError(fmt::format(
        "{}: study \"{}\" has {} grid points but no completed or unstable run yet ({} of "
        "its {} runs failed, the others are pending or running): nothing to report; run "
        "`ccm study run` first (`ccm study status` names the failures)",
        file.string(), data.provenance.study_name, data.status.size(), failed,
        2 * data.status.size()));
  }
  return data;
}

std::size_t count_figures(const reports::ReportContent& content) {
  std::size_t n = 0;
  for (const auto& s : content.sections) n += s.figures.size();
  return n;
}

}  // namespace

int report_command(const ReportArgs& args) {
  return run_reporting_errors([&] {
    if (!(std::isfinite(args.max_error) && args.max_error > 0.0))
      throw StudyInputError(
          fmt::format("--max-error {}: must be a positive number", args.max_error));
    require_writable_output(args.out, "--out");
    const reports::ReportData data = load_study(args.db);
    const auto content = reports::build_report(data, {args.max_error}, reports::current_stamp());
    reports::write_report(content, args.out);
    fmt::print("report: {} ({} figures)\n", (args.out / "index.html").string(),
               count_figures(content));
    return exit_code::completed;
  });
}

}  // namespace ccm
