#include "reports/figures/summary_section.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <map>

#include "reports/figures/impact_table.hpp"
#include "reports/figures/recommendation_map.hpp"
#include "study/recommend/modelling_choices.hpp"
#include "study/recommend/recommendation.hpp"

namespace ccm::reports {
namespace {

using study::ImpactModel;

std::string flag_text(const study::PointDecision& d) {
  if (!d.fitted) return "no fit";
  if (d.fitted->measured_disagrees) return "DIFFERS";
  return d.fitted->reliability.reliable ? "ok" : "UNRELIABLE";
}

std::string reasons_text(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : "; ") + s;
  return out;
}

// Counts over one axis group's usable points.
struct GroupCounts {
  int points = 0, rigid = 0, cheaper_ccm = 0, differs = 0, unreliable = 0;
  double rigid_er_min = std::numeric_limits<double>::infinity();
  double ccm_er_max = 0.0;      // largest ER where the rule says CCM
  double cheap_er_max = 0.0;    // largest ER where CCM is not dearer (RTR <= 1)
  bool rigid_above_all = true;  // every point at ER >= rigid_er_min is rigid
};

std::map<study::AxisLevels, GroupCounts> count_groups(
    const std::vector<study::PointDecision>& decisions) {
  std::map<study::AxisLevels, GroupCounts> groups;
  for (const study::PointDecision& d : decisions) {
    GroupCounts& g = groups[study::fit_axes(d.point->point)];
    const double er = d.point->point.modulus_ratio;
    ++g.points;
    if (d.measured.model == ImpactModel::rigid) {
      ++g.rigid;
      g.rigid_er_min = std::min(g.rigid_er_min, er);
    } else {
      g.ccm_er_max = std::max(g.ccm_er_max, er);
    }
    if (!d.measured.rigid_cheaper) {
      ++g.cheaper_ccm;
      g.cheap_er_max = std::max(g.cheap_er_max, er);
    }
    if (d.fitted && d.fitted->measured_disagrees)
      ++g.differs;
    else if (d.fitted && !d.fitted->reliability.reliable)
      ++g.unreliable;
  }
  for (auto& [axes, g] : groups) g.rigid_above_all = g.ccm_er_max < g.rigid_er_min;
  return groups;
}

std::string group_sentence(const study::AxisLevels& axes, const GroupCounts& g, double max_error) {
  std::string s = axes.empty() ? "The rule" : "With " + study::axes_text(axes) + ", the rule";
  s += fmt::format(" recommends the rigid model at {} of {} measured points", g.rigid, g.points);
  if (g.rigid > 0)
    s += g.rigid_above_all
             ? fmt::format(", all at ER >= {:g}, and every point at such an ER", g.rigid_er_min)
             : fmt::format(" (the smallest ER among them {:g}; CCM is recommended up to ER {:g})",
                           g.rigid_er_min, g.ccm_er_max);
  s += fmt::format(" (max error {:g}). ", max_error);
  if (g.cheaper_ccm > 0)
    s += fmt::format(
        "At {} point(s), up to ER {:g}, CCM is not dearer than the rigid model (measured RTR <= "
        "1): there CCM is both the reference and the cheaper choice. ",
        g.cheaper_ccm, g.cheap_er_max);
  else
    s += "CCM is dearer than the rigid model at every point (measured RTR > 1). ";
  s += fmt::format(
      "The fitted surfaces give the measured answer at {} of {} points; {} differ and {} more "
      "are unreliable (flagged in the table).",
      g.points - g.differs, g.points, g.differs, g.unreliable);
  return s;
}

void add_choices(const ReportData& data, Section& s) {
  if (!data.grid_spec) {
    s.paragraphs.push_back(
        "Modelling choices: not recorded (the store predates schema step 5; run `ccm study run "
        "GRID --db FILE` once on the same grid to record them; nothing is rerun).");
    return;
  }
  std::string text = "Modelling choices (grid file " + data.grid_spec->source.string() + "): ";
  bool first = true;
  for (const study::ModellingChoice& c : study::modelling_choices(*data.grid_spec)) {
    text += (first ? "" : "; ") + c.text();
    first = false;
  }
  s.paragraphs.push_back(text + ".");
}

}  // namespace

Table points_table(const ReportData& data, double max_error) {
  Table t{
      .id = "points",
      .caption = fmt::format(
          "Every grid point: the rigid model's final-state errors against CCM (eqs. "
          "2.37-2.39), the measured cost ratio RTR = TR_ccm / TR_rigid (CPU seconds of the "
          "step loops), the thesis's estimate t_f AIR / ISTS beside it (eqs. 2.40-2.43 with the "
          "structural initial step; for comparison, never decides), w = error / RTR "
          "(informational), the rule at max error {:g} on the measured values and on the "
          "fitted surfaces, and the flag: DIFFERS where they disagree, UNRELIABLE where the "
          "fits' leave-one-out error exceeds the decision margin.",
          max_error),
      .header = {"point", "ER [-]", "RLS [-]", "KE [J]", "other axes", "error u_mean [-]",
                 "error u_max [-]", "error KE [-]", "RTR measured [-]", "RTR thesis estimate [-]",
                 "w u_mean [-]", "w u_max [-]", "w KE [-]", "use (measured)", "use (fitted)",
                 "flag", "why flagged / left out"}};
  const auto decisions = study::decide_grid_points(data.fits, data.grid, max_error);
  std::map<int, const study::PointDecision*> by_index;
  for (const auto& d : decisions) by_index[d.point->point.index] = &d;
  for (const study::PointMetrics& m : data.grid) {
    const auto& p = m.point;
    std::vector<std::string> row = {std::to_string(p.index), cell(p.modulus_ratio),
                                    cell(p.length_ratio), cell(p.kinetic_energy),
                                    study::axes_text(study::fit_axes(p))};
    const auto it = by_index.find(p.index);
    if (it == by_index.end()) {
      row.insert(row.end(), 11, "");
      row.push_back(m.excluded_reason.empty() ? "left out of the fits" : m.excluded_reason);
      t.rows.push_back(std::move(row));
      continue;
    }
    const study::PointDecision& d = *it->second;
    for (double v : {m.final_state.u_mean, m.final_state.u_max, m.final_state.kinetic_energy,
                     m.runtime_ratio, m.runtime_ratio_thesis_estimate, m.weighting.u_mean,
                     m.weighting.u_max, m.weighting.kinetic_energy})
      row.push_back(cell(v));
    row.push_back(std::string(study::to_string(d.measured.model)));
    row.push_back(d.fitted ? std::string(study::to_string(d.fitted->model)) : "-");
    row.push_back(flag_text(d));
    row.push_back(d.fitted ? reasons_text(d.fitted->reliability.reasons) : "");
    t.rows.push_back(std::move(row));
  }
  return t;
}

std::vector<std::string> summary_sentences(const ReportData& data, double max_error) {
  const auto decisions = study::decide_grid_points(data.fits, data.grid, max_error);
  std::vector<std::string> out;
  for (const auto& [axes, g] : count_groups(decisions))
    out.push_back(group_sentence(axes, g, max_error));
  const auto left_out = std::count_if(data.grid.begin(), data.grid.end(),
                                      [](const study::PointMetrics& m) { return !m.usable; });
  if (left_out > 0)
    out.push_back(fmt::format(
        "{} grid point(s) are left out (an unstable or incomparable run; see the table).",
        left_out));
  if (decisions.empty()) out.push_back("No grid point has two comparable runs yet: no answer.");
  return out;
}

Section summary_section(const ReportData& data, double max_error) {
  Section s{.id = "summary", .title = "Answer: which impactor model to use"};
  s.paragraphs.push_back(
      "The " + study::decision_rule_text(max_error) +
      ". RTR is the measured ratio of the two runs' stepping cost; w = error / RTR (the thesis's "
      "weighting function) is shown beside it and never decides. The rule is applied to each "
      "grid point's measured values and to the fitted surfaces (docs/recommendation.md).");
  for (std::string& sentence : summary_sentences(data, max_error))
    s.paragraphs.push_back(std::move(sentence));
  if (auto sentence = impact_sentence(data, max_error)) s.paragraphs.push_back(*sentence);
  add_choices(data, s);
  RecommendationMaps maps = recommendation_maps(data, max_error);
  for (auto& note : maps.notes) s.paragraphs.push_back(std::move(note));
  s.figures = std::move(maps.figures);
  s.tables.push_back(points_table(data, max_error));
  if (auto impact = impact_table(data)) s.tables.push_back(std::move(*impact));
  return s;
}

}  // namespace ccm::reports
