#include "reports/figures/fit_section.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

#include "reports/figures/labels.hpp"
#include "study/metrics/model_errors.hpp"

namespace ccm::reports {
namespace {

using study::ImpactModel;
using study::Metric;

constexpr int kMeshLines = 21;  // surface mesh resolution per axis

// The fitted surface evaluated on a kMeshLines x kMeshLines mesh over its samples' range.
Series surface_mesh(const study::SurfaceFit& fit) {
  Series s{.title = "fitted surface",
           .style = SeriesStyle::surface,
           .surface_columns = kMeshLines,
           .color = 0};
  for (int i = 0; i < kMeshLines; ++i)
    for (int j = 0; j < kMeshLines; ++j) {
      const double x = fit.x_min + (fit.x_max - fit.x_min) * i / (kMeshLines - 1);
      const double y = fit.y_min + (fit.y_max - fit.y_min) * j / (kMeshLines - 1);
      s.x.push_back(x);
      s.y.push_back(y);
      s.z.push_back(fit.surface(x, y));
    }
  return s;
}

Series fit_samples(const study::SurfaceFit& fit) {
  Series s{.title = "simulation data", .color = 1};
  for (const auto& p : fit.samples) {
    s.x.push_back(p.x);
    s.y.push_back(p.y);
    s.z.push_back(p.z);
  }
  return s;
}

std::string fit_caption(const study::MetricFit& f) {
  return fmt::format(
      "{} at KE {:g} J: fitted surface and simulation data (thesis Fig. 2-29, App. B). {}; "
      "x = log10 ER, y = RLS; R^2 = {:.4f}, leave-one-out RMSE = {:.3g}, {} points.",
      metric_label(f.metric), f.kinetic_energy, surface_equation(f.fit.surface, "z"),
      f.fit.r_squared, f.fit.loo_rmse, f.fit.samples.size());
}

Figure fit_figure(const study::MetricFit& f) {
  PlotSpec plot{.title = fmt::format("{}, KE {:g} J", study::to_string(f.metric), f.kinetic_energy),
                .x_label = "log10 ER [-]",
                .y_label = "RLS [-]",
                .z_label = metric_label(f.metric),
                .three_d = true};
  plot.series = {surface_mesh(f.fit), fit_samples(f.fit)};
  return make_figure(
      fmt::format("fig-fit-{}-ke-{:g}", study::to_string(f.metric), f.kinetic_energy),
      fit_caption(f), plot);
}

Table fits_table(const study::StudyFits& fits) {
  Table t{.id = "fits",
          .caption =
              "Every fitted surface over x = log10 ER, y = RLS, one per metric and KE "
              "(App. B), and the points and (metric, KE) pairs left out.",
          .header = {"metric", "KE [J]", "degree in x", "degree in y", "equation", "R^2",
                     "leave-one-out RMSE", "points"}};
  for (const auto& f : fits.fits)
    t.rows.push_back({std::string(study::to_string(f.metric)), cell(f.kinetic_energy),
                      std::to_string(f.fit.surface.degree.x),
                      std::to_string(f.fit.surface.degree.y), surface_equation(f.fit.surface, "z"),
                      cell(f.fit.r_squared), cell(f.fit.loo_rmse),
                      std::to_string(f.fit.samples.size())});
  for (const auto& e : fits.excluded)
    t.rows.push_back({"(point " + std::to_string(e.point_index) + " left out)",
                      cell(e.kinetic_energy), "", "", e.reason, "", "", ""});
  for (const auto& note : fits.notes)
    t.rows.push_back({"(not fitted)", "", "", "", note, "", "", ""});
  return t;
}

// Final-state errors of every usable grid point against its runtime ratio.
Figure error_against_runtime_ratio(const ReportData& data) {
  PlotSpec plot{.title = "Final-state error against runtime ratio, every usable point",
                .x_label = "RTR = NT_CCM / NT_rigid [-]",
                .y_label = "final-state error of rigid against CCM [-]"};
  const std::pair<Metric, const char*> metrics[] = {{Metric::final_u_mean, "u_mean"},
                                                    {Metric::final_u_max, "u_max"},
                                                    {Metric::final_kinetic_energy, "artifact KE"}};
  for (std::size_t i = 0; i < std::size(metrics); ++i) {
    Series s{.title = std::string("rigid vs CCM, ") + metrics[i].second, .color = int(i)};
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
                     "Final-state errors (eqs. 2.37-2.39) against the runtime ratio RTR "
                     "(eq. 2.40): what the rigid model's speed costs in accuracy, per point.",
                     plot);
}

double mesh_scale(const study::GridPoint& p) { return p.other_axes.at("mesh_scale"); }

struct ConvergenceRun {
  const study::RunRecord* run = nullptr;
  double error_ke = 0.0, error_u_max = 0.0;  // final-state, against the finest CCM run
};

// Each completed convergence run against the finest completed CCM run of its (ER, RLS, KE).
std::vector<ConvergenceRun> convergence_runs(const ReportData& data) {
  using Key = std::tuple<double, double, double>;
  auto key = [](const study::GridPoint& p) {
    return Key{p.modulus_ratio, p.length_ratio, p.kinetic_energy};
  };
  std::map<Key, const study::RunRecord*> finest;
  for (const auto& r : data.runs)
    if (is_convergence_point(r.point) && r.completed() && r.model == ImpactModel::ccm) {
      auto& best = finest[key(r.point)];
      if (!best || mesh_scale(r.point) < mesh_scale(best->point)) best = &r;
    }
  std::vector<ConvergenceRun> out;
  for (const auto& r : data.runs) {
    const auto it = finest.find(key(r.point));
    if (!is_convergence_point(r.point) || !r.completed() || it == finest.end() ||
        it->second->artifact.time.size() != r.artifact.time.size())
      continue;
    const auto& ref = it->second->artifact;
    out.push_back({&r, study::final_state_error(ref.kinetic_energy, r.artifact.kinetic_energy),
                   study::final_state_error(ref.u_max, r.artifact.u_max)});
  }
  return out;
}

Table convergence_table(const std::vector<ConvergenceRun>& runs) {
  Table t{
      .id = "convergence",
      .caption =
          "Convergence runs against the finest CCM run of their point; accuracy per "
          "second = (1 - final-state KE error) / wall time.",
      .header = {"point", "case", "model", "mesh scale", "elements", "wall time [s]",
                 "final-state KE error", "final-state u_max error", "accuracy per second [1/s]"}};
  for (const auto& c : runs) {
    const auto& r = *c.run;
    t.rows.push_back({std::to_string(r.point.index), case_label(r.point),
                      std::string(study::to_string(r.model)), cell(mesh_scale(r.point)),
                      std::to_string(r.n_elements), cell(r.wall_seconds), cell(c.error_ke),
                      cell(c.error_u_max),
                      cell(r.wall_seconds > 0 ? (1.0 - c.error_ke) / r.wall_seconds
                                              : std::numeric_limits<double>::quiet_NaN())});
  }
  return t;
}

Figure convergence_figure(const std::vector<ConvergenceRun>& runs) {
  PlotSpec plot{.title = "Convergence mode: error against wall time",
                .x_label = "wall time of the run [s]",
                .y_label = "final-state KE error against finest CCM [-]"};
  for (ImpactModel m : {ImpactModel::ccm, ImpactModel::rigid}) {
    Series s{.title = model_label(m), .color = m == ImpactModel::ccm ? 0 : 1};
    for (const auto& c : runs)
      if (c.run->model == m) {
        s.x.push_back(c.run->wall_seconds);
        s.y.push_back(c.error_ke);
      }
    plot.series.push_back(std::move(s));
  }
  plot.log_x = spans_decades(all_values(plot, 0));
  return make_figure("fig-convergence-error-vs-time",
                     "Each convergence run's final-state KE error against the finest CCM run "
                     "of its point, against its wall time, by model.",
                     plot);
}

}  // namespace

std::string surface_equation(const study::PolynomialSurface& surface, const std::string& z) {
  std::string out = z + " =";
  bool first = true;
  for (const auto& t : surface.terms) {
    const double c = t.coefficient;
    std::string monomial;
    if (t.power_x > 0) monomial += t.power_x == 1 ? " x" : fmt::format(" x^{}", t.power_x);
    if (t.power_y > 0) monomial += t.power_y == 1 ? " y" : fmt::format(" y^{}", t.power_y);
    out += fmt::format(" {}{:.4g}{}", first ? (c < 0 ? "-" : "") : (c < 0 ? "- " : "+ "),
                       std::abs(c), monomial);
    first = false;
  }
  return first ? out + " 0" : out;
}

Section fit_section(const ReportData& data) {
  Section s{.id = "weighting", .title = "Weighting functions and fitted surfaces"};
  s.paragraphs.push_back(
      "w = final-state error / RTR (thesis 2.8): a large w says the rigid model's error is "
      "large for what CCM costs, so use CCM; a small w says the rigid model is enough. Each "
      "surface is a least-squares polynomial in x = log10 ER and y = RLS whose degree was "
      "chosen by leave-one-out cross-validation (App. B).");
  for (const auto& f : data.fits.fits)
    if (f.metric == Metric::w_u_mean || f.metric == Metric::w_u_max ||
        f.metric == Metric::w_kinetic_energy || f.metric == Metric::runtime_ratio)
      s.figures.push_back(fit_figure(f));
  if (s.figures.empty())
    s.paragraphs.push_back("No surface could be fitted: see the notes in the table below.");
  s.tables.push_back(fits_table(data.fits));
  return s;
}

Section error_runtime_section(const ReportData& data) {
  Section s{.id = "error-runtime", .title = "Error against runtime"};
  if (std::any_of(data.grid.begin(), data.grid.end(), [](auto& m) { return m.usable; }))
    s.figures.push_back(error_against_runtime_ratio(data));
  const auto runs = convergence_runs(data);
  if (runs.empty()) {
    s.paragraphs.push_back(
        "This study has no completed convergence runs (grid [convergence] table), so no "
        "accuracy per second is shown.");
    return s;
  }
  s.figures.push_back(convergence_figure(runs));
  s.tables.push_back(convergence_table(runs));
  return s;
}

}  // namespace ccm::reports
