#include "reports/figures/fit_section.hpp"

#include <fmt/format.h>

#include "reports/figures/labels.hpp"
#include "reports/figures/surface_series.hpp"

namespace ccm::reports {
namespace {

using study::Metric;

// ", damping 1" for a fit of an axis group; "" on a plain grid.
std::string group_suffix(const study::AxisLevels& axes, const char* separator) {
  std::string out;
  for (const auto& [name, value] : axes)
    out += fmt::format("{}{}{}{:g}", separator, name, separator[0] == '-' ? "-" : " ", value);
  return out;
}

std::string fit_caption(const study::MetricFit& f) {
  return fmt::format(
      "{} at KE {:g} J{}: fitted surface and simulation data (thesis Fig. 2-29, App. B; fitted "
      "in log10, so that 10^z is never negative). {}; x = log10 ER, y = RLS; {}.",
      metric_label(f.metric), f.kinetic_energy, group_suffix(f.axes, ", "),
      surface_equation(f.fit.surface, "z"), fit_quality(f.fit));
}

Figure fit_figure(const study::MetricFit& f) {
  PlotSpec plot{.title = fmt::format("{}, KE {:g} J{}", study::to_string(f.metric),
                                     f.kinetic_energy, group_suffix(f.axes, ", ")),
                .x_label = "log10 ER [-]",
                .y_label = "RLS [-]",
                .z_label = metric_label(f.metric),
                .three_d = true};
  const std::string which =
      fmt::format("rigid vs CCM, KE {:g} J{}", f.kinetic_energy, group_suffix(f.axes, ", "));
  plot.series = {surface_mesh(f.fit, "fitted surface, " + which, 0),
                 surface_samples(f.fit, "simulation data, " + which, 1)};
  plot.log_z = !study::fitted_in_log10(f.metric) && spans_decades(all_values(plot, 2));
  return make_figure(fmt::format("fig-fit-{}-ke-{:g}{}", study::to_string(f.metric),
                                 f.kinetic_energy, group_suffix(f.axes, "-")),
                     fit_caption(f), std::move(plot));
}

bool is_weighting_figure_metric(Metric m) {
  return m == Metric::log10_w_u_mean || m == Metric::log10_w_u_max ||
         m == Metric::log10_w_kinetic_energy || m == Metric::log10_runtime_ratio;
}

}  // namespace

Table fits_table(const study::StudyFits& fits) {
  Table t{.id = "fits",
          .caption =
              "Every fitted surface over x = log10 ER, y = RLS, one per metric, KE and level "
              "of the grid's other axes (App. B), and the points and (metric, KE) pairs left "
              "out. log10_* metrics are fitted in log10 (their RMSE is in decades).",
          .header = {"metric", "KE [J]", "other axes", "degree in x", "degree in y", "equation",
                     "R^2", "leave-one-out RMSE", "points"}};
  for (const auto& f : fits.fits)
    t.rows.push_back({std::string(study::to_string(f.metric)), cell(f.kinetic_energy),
                      study::axes_text(f.axes), std::to_string(f.fit.surface.degree.x),
                      std::to_string(f.fit.surface.degree.y), surface_equation(f.fit.surface, "z"),
                      cell(f.fit.r_squared), cell(f.fit.loo_rmse),
                      std::to_string(f.fit.samples.size())});
  for (const auto& e : fits.excluded)
    t.rows.push_back({"(point " + std::to_string(e.point_index) + " left out)",
                      cell(e.kinetic_energy), "", "", "", e.reason, "", "", ""});
  for (const auto& note : fits.notes)
    t.rows.push_back({"(not fitted)", "", "", "", "", note, "", "", ""});
  return t;
}

Section fit_section(const ReportData& data) {
  Section s{.id = "weighting", .title = "Weighting functions and fitted surfaces"};
  s.paragraphs.push_back(
      "w = final-state error / RTR (thesis 2.8): a large w says the rigid model's error is "
      "large for what CCM costs, so use CCM; a small w says the rigid model is enough. Each "
      "surface is a least-squares polynomial in x = log10 ER and y = RLS whose degree was "
      "chosen by leave-one-out cross-validation among every degree up to 3 in x and 2 in y, the "
      "constant included (App. B). RTR and w are fitted in log10 (they span decades and are "
      "positive); the errors as they are. The table lists every fit, the normalised runtimes' "
      "(Fig. 2-28) and the errors' included.");
  for (const auto& f : data.fits.fits)
    if (is_weighting_figure_metric(f.metric)) s.figures.push_back(fit_figure(f));
  if (data.grid.empty())
    s.paragraphs.push_back(
        "No metrics are stored for this study (a store written before metrics existed, or a "
        "`ccm study run` that did not reach its end): run `ccm study run GRID --db FILE` again "
        "to derive them; it skips every run already completed or unstable.");
  else if (s.figures.empty())
    s.paragraphs.push_back("No surface could be fitted: see the notes in the table below.");
  s.tables.push_back(fits_table(data.fits));
  return s;
}

}  // namespace ccm::reports
