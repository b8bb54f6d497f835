#include "reports/figures/impact_table.hpp"

#include <fmt/format.h>

#include <array>
#include <map>

namespace ccm::reports {
namespace {

// The metric whose error is the largest (ties to the first in IM order).
std::string worst_metric(const study::ImpactErrors& e) {
  const std::array<std::pair<double, const char*>, 4> all = {
      {{e.peak_force, "peak force"},
       {e.indentation, "indentation"},
       {e.contact_duration, "contact duration"},
       {e.rebound_speed, "rebound speed"}}};
  auto worst = all[0];
  for (const auto& m : all)
    if (m.first > worst.first) worst = m;
  return worst.second;
}

}  // namespace

std::optional<Table> impact_table(const ReportData& data) {
  Table t{.id = "impact",
          .caption =
              "The designer's metrics of every grid point whose runs kept the impactor's "
              "history (docs/metrics.md, IM.1-IM.5): peak contact force (the impactor's "
              "momentum change over each output interval), deepest indentation of the "
              "artifact, contact duration and rebound speed, of the CCM and the rigid run, "
              "and the rigid run's error in each (|r - c| / max(|r|, |c|); the rebound's "
              "over the approach speed). Shown beside the rule's final-state errors; they "
              "do not decide.",
          .header = {"point", "ER [-]", "RLS [-]", "KE [J]", "other axes", "peak force CCM [N]",
                     "peak force rigid [N]", "error peak force [-]", "indentation CCM [m]",
                     "indentation rigid [m]", "error indentation [-]", "contact duration CCM [s]",
                     "contact duration rigid [s]", "error contact duration [-]",
                     "rebound speed CCM [m/s]", "rebound speed rigid [m/s]",
                     "error rebound speed [-]", "worst error [-]"}};
  for (const study::PointMetrics& m : data.grid) {
    if (!m.impact_errors || !m.ccm_impact || !m.rigid_impact) continue;
    const auto& p = m.point;
    const study::ImpactQuantities &c = *m.ccm_impact, &r = *m.rigid_impact;
    const study::ImpactErrors& e = *m.impact_errors;
    std::vector<std::string> row = {std::to_string(p.index), cell(p.modulus_ratio),
                                    cell(p.length_ratio), cell(p.kinetic_energy),
                                    study::axes_text(study::fit_axes(p))};
    for (double v : {c.peak_force, r.peak_force, e.peak_force, c.indentation, r.indentation,
                     e.indentation, c.contact_duration, r.contact_duration, e.contact_duration,
                     c.rebound_speed, r.rebound_speed, e.rebound_speed, e.worst()})
      row.push_back(cell(v));
    t.rows.push_back(std::move(row));
  }
  if (t.rows.empty()) return std::nullopt;
  return t;
}

std::optional<std::string> impact_sentence(const ReportData& data, double max_error) {
  int points = 0, within = 0;
  std::map<std::string, int> worst;
  for (const study::PointMetrics& m : data.grid) {
    if (!m.impact_errors) continue;
    ++points;
    if (m.impact_errors->worst() <= max_error) ++within;
    ++worst[worst_metric(*m.impact_errors)];
  }
  if (points == 0) return std::nullopt;
  std::string most;
  int count = -1;
  for (const auto& [name, n] : worst)
    if (n > count) most = name, count = n;
  return fmt::format(
      "On the designer's metrics (peak force, indentation, contact duration, rebound speed; "
      "docs/metrics.md), the rigid model is within {:g} on all four at {} of {} points; the "
      "largest error is most often the {} ({} points). They are shown beside the rule and do not "
      "decide.",
      max_error, within, points, most, count);
}

}  // namespace ccm::reports
