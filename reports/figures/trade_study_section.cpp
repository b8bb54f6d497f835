#include "reports/figures/trade_study_section.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "reports/figures/labels.hpp"
#include "reports/figures/normalised_runtime_figures.hpp"

namespace ccm::reports {
namespace {

using study::ImpactModel;
using study::Metric;
using study::PointMetrics;
using study::RunRecord;

constexpr std::array<ImpactModel, 2> kModels = {ImpactModel::ccm, ImpactModel::rigid};

std::vector<const RunRecord*> grid_runs(const ReportData& data) {
  std::vector<const RunRecord*> out;
  for (const auto& r : data.runs)
    if (!is_convergence_point(r.point)) out.push_back(&r);
  return out;
}

std::vector<study::GridPoint> grid_points(const ReportData& data) {
  std::vector<study::GridPoint> out;
  for (const auto& s : data.status)
    if (!is_convergence_point(s.point)) out.push_back(s.point);
  return out;
}

// One series per model and KE level of `value(run)` against the grid point index.
PlotSpec per_point_plot(const ReportData& data, std::string title, std::string y_label,
                        const std::function<double(const RunRecord&)>& value) {
  PlotSpec plot{.title = std::move(title),
                .x_label = "grid point (case) index [-]",
                .y_label = std::move(y_label),
                .integer_x = true};
  const auto levels = kinetic_energy_levels(grid_points(data));
  for (std::size_t k = 0; k < levels.size(); ++k)
    for (std::size_t m = 0; m < kModels.size(); ++m) {
      Series s{.title = fmt::format("{}, KE {:g} J", model_label(kModels[m]), levels[k]),
               .color = static_cast<int>(2 * k + m)};
      for (const RunRecord* r : grid_runs(data))
        if (r->model == kModels[m] && r->point.kinetic_energy == levels[k] && value(*r) > 0.0) {
          s.x.push_back(r->point.index);
          s.y.push_back(value(*r));
        }
      plot.series.push_back(std::move(s));
    }
  plot.log_y = spans_decades(all_values(plot, 1));
  return plot;
}

std::vector<Figure> runtime_figures(const ReportData& data) {
  struct Item {
    const char* id;
    const char* caption;
    const char* title;
    const char* y_label;
    double (*value)(const RunRecord&);
  };
  const Item items[] = {
      {"fig-total-runtime", "Measured wall time of every run, both models (thesis Fig. 2-16).",
       "Total runtime per grid point", "wall time of the run [s]",
       [](const RunRecord& r) { return r.wall_seconds; }},
      {"fig-iteration-time",
       "Average wall time of one time step, AIR (eq. 2.41; thesis Fig. 2-17).",
       "Average iteration time per grid point", "AIR, wall time per step [s]",
       [](const RunRecord& r) { return r.average_iteration_seconds; }},
      {"fig-initial-stable-step", "Initial stable time step, ISTS (eq. 2.42; thesis Fig. 2-18).",
       "Initial stable time step per grid point", "ISTS [s]",
       [](const RunRecord& r) { return r.initial_stable_dt; }}};
  std::vector<Figure> out;
  for (const Item& item : items) {
    PlotSpec plot = per_point_plot(data, item.title, item.y_label, item.value);
    if (!all_values(plot, 0).empty())  // no grid run stored yet: no figure
      out.push_back(make_figure(item.id, item.caption, std::move(plot)));
  }
  return out;
}

const RunRecord* find_run(const ReportData& data, int point_index, ImpactModel model) {
  for (const auto& r : data.runs)
    if (r.point.index == point_index && r.model == model) return &r;
  return nullptr;
}

std::vector<Figure> corner_history_figures(const ReportData& data) {
  std::vector<Figure> out;
  for (const study::GridPoint& p : corner_points(grid_points(data))) {
    PlotSpec plot{.title = "Artifact kinetic energy, " + case_label(p),
                  .x_label = "time [s]",
                  .y_label = "artifact kinetic energy [J]"};
    for (std::size_t m = 0; m < kModels.size(); ++m)
      if (const RunRecord* r = find_run(data, p.index, kModels[m]))
        plot.series.push_back(Series{
            .title = model_label(kModels[m]) + ", " + case_label(p) + " (" + r->verdict + ")",
            .style = SeriesStyle::lines,
            .x = r->artifact.time,
            .y = r->artifact.kinetic_energy,
            .color = static_cast<int>(m)});
    if (plot.series.empty()) continue;
    out.push_back(make_figure(fmt::format("fig-ke-history-point-{}", p.index),
                              "Artifact kinetic energy of CCM against rigid at the corner point " +
                                  case_label(p) + " (thesis Fig. 2-19).",
                              std::move(plot)));
  }
  return out;
}

// One series per (KE, RLS) of `metric` against ER over the usable grid points.
PlotSpec error_plot(const std::vector<PointMetrics>& grid, Metric metric) {
  PlotSpec plot{.title = std::string(metric_label(metric)) + " for all cases",
                .x_label = "ER = E_impactor / E_artifact [-]",
                .y_label = metric_label(metric),
                .log_x = true};
  std::vector<std::pair<double, double>> cases;  // (KE, RLS)
  for (const auto& m : grid)
    if (m.usable) cases.emplace_back(m.point.kinetic_energy, m.point.length_ratio);
  std::sort(cases.begin(), cases.end());
  cases.erase(std::unique(cases.begin(), cases.end()), cases.end());
  for (std::size_t c = 0; c < cases.size(); ++c) {
    Series s{
        .title = fmt::format("rigid vs CCM, KE {:g} J, RLS {:g}", cases[c].first, cases[c].second),
        .style = SeriesStyle::linespoints,
        .color = static_cast<int>(c)};
    std::vector<const PointMetrics*> pts;
    for (const auto& m : grid)
      if (m.usable && m.point.kinetic_energy == cases[c].first &&
          m.point.length_ratio == cases[c].second)
        pts.push_back(&m);
    std::sort(pts.begin(), pts.end(),
              [](auto* a, auto* b) { return a->point.modulus_ratio < b->point.modulus_ratio; });
    for (const PointMetrics* m : pts) {
      s.x.push_back(m->point.modulus_ratio);
      s.y.push_back(study::metric_value(*m, metric));
    }
    plot.series.push_back(std::move(s));
  }
  plot.log_y = spans_decades(all_values(plot, 1));
  return plot;
}

std::vector<Figure> error_figures(const ReportData& data) {
  struct Item {
    Metric metric;
    const char* id;
    const char* thesis;
  };
  const Item items[] = {
      {Metric::cumulative_u_mean, "fig-cumulative-u-mean", "eq. 2.34; Fig. 2-22"},
      {Metric::cumulative_u_max, "fig-cumulative-u-max", "eq. 2.35; Fig. 2-23"},
      {Metric::cumulative_kinetic_energy, "fig-cumulative-ke", "eq. 2.36; Fig. 2-24"},
      {Metric::final_u_mean, "fig-final-u-mean", "eq. 2.37; Fig. 2-25"},
      {Metric::final_u_max, "fig-final-u-max", "eq. 2.38; Fig. 2-26"},
      {Metric::final_kinetic_energy, "fig-final-ke", "eq. 2.39; Fig. 2-27"}};
  std::vector<Figure> out;
  for (const Item& item : items) {
    const PlotSpec plot = error_plot(data.grid, item.metric);
    if (all_values(plot, 0).empty()) continue;
    out.push_back(make_figure(item.id,
                              metric_label(item.metric) + " of the rigid model against CCM at " +
                                  "every usable grid point (" + item.thesis + ").",
                              plot));
  }
  return out;
}

}  // namespace

std::vector<study::GridPoint> corner_points(const std::vector<study::GridPoint>& grid) {
  if (grid.empty()) return {};
  auto [er_lo, er_hi] = std::minmax_element(
      grid.begin(), grid.end(), [](auto& a, auto& b) { return a.modulus_ratio < b.modulus_ratio; });
  auto [rls_lo, rls_hi] = std::minmax_element(
      grid.begin(), grid.end(), [](auto& a, auto& b) { return a.length_ratio < b.length_ratio; });
  const double ke = std::max_element(grid.begin(), grid.end(), [](auto& a, auto& b) {
                      return a.kinetic_energy < b.kinetic_energy;
                    })->kinetic_energy;
  std::vector<study::GridPoint> out;
  for (double er : {er_hi->modulus_ratio, er_lo->modulus_ratio})
    for (double rls : {rls_lo->length_ratio, rls_hi->length_ratio})
      for (const auto& p : grid)
        if (p.modulus_ratio == er && p.length_ratio == rls && p.kinetic_energy == ke &&
            std::none_of(out.begin(), out.end(), [&](auto& q) { return q.index == p.index; }))
          out.push_back(p);
  return out;
}

Section trade_study_section(const ReportData& data) {
  Section s{.id = "trade-study", .title = "Trade study: CCM against the rigid impactor"};
  s.paragraphs.push_back(fmt::format(
      "{} grid points ({} of their runs stored, {} points with usable metrics; the "
      "convergence runs are in their own section). Errors are of the rigid model against CCM "
      "(thesis 2.8, eqs. 2.34-2.39); points where either run went unstable are left out of the "
      "error figures and listed in the stability table.",
      grid_points(data).size(), grid_runs(data).size(),
      std::count_if(data.grid.begin(), data.grid.end(), [](auto& m) { return m.usable; })));
  for (auto* group :
       {&runtime_figures, &corner_history_figures, &error_figures, &normalised_runtime_figures})
    for (Figure& f : (*group)(data)) s.figures.push_back(std::move(f));
  return s;
}

}  // namespace ccm::reports
