#include "reports/figures/stability_section.hpp"

#include <fmt/format.h>

#include "reports/figures/labels.hpp"

namespace ccm::reports {
namespace {

using study::ImpactModel;

const study::RunRecord* find_run(const ReportData& data, int point_index, ImpactModel model) {
  for (const auto& r : data.runs)
    if (r.point.index == point_index && r.model == model) return &r;
  return nullptr;
}

std::string status_text(const std::optional<db::RunStatus>& status) {
  return status ? std::string(db::to_string(*status)) : std::string("pending");
}

std::vector<std::string> stability_row(const db::PointStatus& s, ImpactModel model,
                                       const study::RunRecord* run) {
  const auto& status = model == ImpactModel::ccm ? s.ccm : s.rigid;
  std::vector<std::string> row = {std::to_string(s.point.index), case_label(s.point),
                                  std::string(study::to_string(model)), status_text(status)};
  if (run == nullptr) {
    row.insert(row.end(), {s.reason, "-", "-", "-", "-", "-"});
    return row;
  }
  row.insert(row.end(),
             {run->reason, cell(run->dt_min), cell(run->dt_max), cell(run->max_energy_error),
              std::to_string(run->steps), run->completed() ? "-" : cell(run->unstable_time)});
  return row;
}

}  // namespace

Table stability_table(const ReportData& data) {
  Table t{.id = "stability",
          .caption =
              "Every run: verdict, reason, time-step range, largest relative "
              "energy-balance error.",
          .header = {"point", "case", "model", "verdict", "reason", "dt min [s]", "dt max [s]",
                     "max energy-balance error [-]", "steps", "unstable at [s]"}};
  for (const db::PointStatus& s : data.status)
    for (ImpactModel m : {ImpactModel::ccm, ImpactModel::rigid})
      t.rows.push_back(stability_row(s, m, find_run(data, s.point.index, m)));
  return t;
}

Section stability_section(const ReportData& data) {
  Section s{.id = "stability", .title = "Stability"};
  int unstable = 0, failed = 0, pending = 0;
  for (const db::PointStatus& p : data.status)
    for (const auto& run : {p.ccm, p.rigid}) {
      unstable += run == db::RunStatus::unstable;
      failed += run == db::RunStatus::failed;
      pending += !run || run == db::RunStatus::running;
    }
  s.paragraphs.push_back(fmt::format(
      "{} runs: {} unstable, {} failed, {} not finished. Unstable and failed runs keep their "
      "point out of the fits.",
      2 * data.status.size(), unstable, failed, pending));
  s.tables.push_back(stability_table(data));
  return s;
}

}  // namespace ccm::reports
