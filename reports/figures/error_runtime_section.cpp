#include "reports/figures/error_runtime_section.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <map>
#include <tuple>

#include "reports/figures/labels.hpp"

namespace ccm::reports {
namespace {

using study::ConvergenceRow;
using study::ImpactModel;
using study::Metric;

// Final-state errors of every usable grid point against its runtime ratio.
Figure error_against_runtime_ratio(const ReportData& data) {
  PlotSpec plot{.title = "Final-state error against runtime ratio, every usable point",
                .x_label = "RTR = TR_CCM / TR_rigid, measured [-]",
                .y_label = "final-state error of rigid against CCM [-]"};
  const std::pair<Metric, const char*> metrics[] = {{Metric::final_u_mean, "u_mean"},
                                                    {Metric::final_u_max, "u_max"},
                                                    {Metric::final_kinetic_energy, "artifact KE"}};
  for (std::size_t i = 0; i < std::size(metrics); ++i) {
    Series s{.title = fmt::format("rigid vs CCM, {}, every usable case", metrics[i].second),
             .color = int(i)};
    for (const auto& m : data.grid)
      if (m.usable) {
        s.x.push_back(m.runtime_ratio);
        s.y.push_back(study::metric_value(m, metrics[i].first));
      }
    plot.series.push_back(std::move(s));
  }
  plot.log_x = spans_decades(all_values(plot, 0));
  plot.log_y = spans_decades(all_values(plot, 1));
  return make_figure("fig-error-vs-runtime-ratio",
                     "Final-state errors (eqs. 2.37-2.39) against the measured cost ratio RTR "
                     "= TR_ccm / TR_rigid: what the rigid model's speed costs in accuracy, per "
                     "point.",
                     std::move(plot));
}

std::tuple<double, double, double> case_key(const study::GridPoint& p) {
  return {p.modulus_ratio, p.length_ratio, p.kinetic_energy};
}

// One series per (model, case) of `value(row)` against `x(row)`, in mesh-scale order.
PlotSpec per_case_plot(const std::vector<ConvergenceRow>& rows, PlotSpec plot,
                       const std::function<double(const ConvergenceRow&)>& x,
                       const std::function<double(const ConvergenceRow&)>& y) {
  std::map<std::tuple<ImpactModel, double, double, double>, std::size_t> series_of;
  for (const ConvergenceRow& r : rows) {
    const auto [er, rls, ke] = case_key(r.point);
    auto [it, added] = series_of.try_emplace({r.model, er, rls, ke}, plot.series.size());
    if (added)
      plot.series.push_back(Series{.title = model_label(r.model) + ", " + main_case_label(r.point),
                                   .style = SeriesStyle::linespoints,
                                   .color = static_cast<int>(plot.series.size())});
    plot.series[it->second].x.push_back(x(r));
    plot.series[it->second].y.push_back(y(r));
  }
  plot.log_x = spans_decades(all_values(plot, 0));
  plot.log_y = spans_decades(all_values(plot, 1));
  return plot;
}

std::vector<Figure> convergence_figures(const std::vector<ConvergenceRow>& rows) {
  const auto error_plot = per_case_plot(
      rows,
      {.title = "Convergence mode: error against wall time",
       .x_label = "wall time of the run [s]",
       .y_label = "final-state KE error against the finest CCM run [-]"},
      [](const ConvergenceRow& r) { return r.wall_seconds; },
      [](const ConvergenceRow& r) { return r.final_state.kinetic_energy; });
  const auto accuracy_plot = per_case_plot(
      rows,
      {.title = "Convergence mode: accuracy per second",
       .x_label = "mesh scale (factor on both mesh sizes) [-]",
       .y_label = "accuracy per second = (1 - KE error) / wall time [1/s]"},
      [](const ConvergenceRow& r) { return study::mesh_scale(r.point); },
      [](const ConvergenceRow& r) { return study::accuracy_per_second(r); });
  return {make_figure("fig-convergence-error-vs-time",
                      "Each convergence run's final-state KE error (eq. 2.39) against the "
                      "finest CCM run of its point, against its wall time, by model and case.",
                      error_plot),
          make_figure("fig-convergence-accuracy-per-second",
                      "Each model's accuracy per second at each mesh scale of the convergence "
                      "mode: (1 - final-state KE error against the finest CCM run) / wall time.",
                      accuracy_plot)};
}

}  // namespace

std::vector<ConvergenceRow> convergence_rows(const ReportData& data) {
  std::vector<study::RunRecord> runs;
  for (const auto& r : data.runs)
    if (is_convergence_point(r.point)) runs.push_back(r);
  std::vector<ConvergenceRow> rows;
  for (const ConvergenceRow& r : study::compare_convergence_runs(runs))
    if (r.usable) rows.push_back(r);
  std::stable_sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) {
    return std::tuple(case_key(a.point), a.model, study::mesh_scale(a.point)) <
           std::tuple(case_key(b.point), b.model, study::mesh_scale(b.point));
  });
  return rows;
}

Table convergence_table(const std::vector<ConvergenceRow>& rows) {
  Table t{.id = "convergence",
          .caption =
              "Convergence runs against the finest CCM run of their case: final-state errors "
              "(eqs. 2.37-2.39) and accuracy per second = (1 - final-state KE error) / wall "
              "time.",
          .header = {"point", "case", "model", "role", "mesh scale [-]", "elements",
                     "wall time [s]", "final-state u_mean error [-]", "final-state u_max error [-]",
                     "final-state KE error [-]", "accuracy per second [1/s]"}};
  for (const ConvergenceRow& r : rows)
    t.rows.push_back({std::to_string(r.point.index), main_case_label(r.point),
                      std::string(study::to_string(r.model)),
                      r.reference ? "reference (finest CCM)" : "compared",
                      cell(study::mesh_scale(r.point)), std::to_string(r.n_elements),
                      cell(r.wall_seconds), cell(r.final_state.u_mean), cell(r.final_state.u_max),
                      cell(r.final_state.kinetic_energy), cell(study::accuracy_per_second(r))});
  return t;
}

Section error_runtime_section(const ReportData& data) {
  Section s{.id = "error-runtime", .title = "Error against runtime"};
  if (std::any_of(data.grid.begin(), data.grid.end(), [](auto& m) { return m.usable; }))
    s.figures.push_back(error_against_runtime_ratio(data));
  const auto rows = convergence_rows(data);
  if (rows.empty()) {
    s.paragraphs.push_back(
        "This study has no completed convergence runs (grid [convergence] table), so no "
        "accuracy per second is shown.");
    return s;
  }
  s.paragraphs.push_back(
      "The first figure is the grid: every usable point's final-state errors against its "
      "runtime ratio. The others are the convergence mode: each case of the grid's "
      "[convergence] table is run at several mesh scales and every run is compared with the "
      "finest CCM run of its case (which so has error 0).");
  for (Figure& f : convergence_figures(rows)) s.figures.push_back(std::move(f));
  s.tables.push_back(convergence_table(rows));
  return s;
}

}  // namespace ccm::reports
