#include "reports/figures/recommendation_map.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "reports/figures/labels.hpp"
#include "study/recommend/recommendation.hpp"

namespace ccm::reports {
namespace {

using study::ImpactModel;

std::string group_title(const study::AxisLevels& axes) {
  return axes.empty() ? "" : ", " + study::axes_text(axes);
}

std::string group_id(const study::AxisLevels& axes) {
  std::string out;
  for (const auto& [name, value] : axes) out += fmt::format("-{}-{:g}", name, value);
  return out;
}

// The measured grid points of one map, as markers coloured by their measured answer.
void add_measured_points(const ReportData& data, const study::AxisLevels& axes, double ke,
                         double max_error, const std::string& at, PlotSpec& plot) {
  Series ccm{.title = "measured point at " + at + ": CCM by the rule",
             .style = SeriesStyle::points,
             .color = 3};
  Series rigid{.title = "measured point at " + at + ": rigid by the rule",
               .style = SeriesStyle::points,
               .color = 4};
  for (const study::PointMetrics& m : data.grid) {
    if (!m.usable || m.point.kinetic_energy != ke || study::fit_axes(m.point) != axes) continue;
    const auto d = study::decide_model(study::measured_inputs(m), max_error);
    Series& s = d.model == ImpactModel::ccm ? ccm : rigid;
    s.x.push_back(m.point.modulus_ratio);
    s.y.push_back(m.point.length_ratio);
  }
  for (Series* s : {&ccm, &rigid})
    if (!s->empty()) plot.series.push_back(std::move(*s));
}

std::optional<Figure> map_figure(const ReportData& data, const study::AxisLevels& axes, double ke,
                                 double max_error) {
  const auto cells = recommendation_cells(data.fits, data.grid, axes, ke, max_error);
  if (cells.empty()) return std::nullopt;
  const std::string at = fmt::format("KE {:g} J{}", ke, group_title(axes));
  PlotSpec plot{.title = fmt::format("Recommended model, {}, max error {:g}", at, max_error),
                .x_label = "ER = E_impactor / E_artifact [-]",
                .y_label = "RLS = D_impactor / L_artifact [-]",
                .log_x = true};
  // Cells tile the plane: half the spacing of their centres (in decades of ER, and in RLS).
  const auto [x_lo, x_hi] = std::minmax_element(cells.begin(), cells.end(), [](auto& a, auto& b) {
    return a.modulus_ratio < b.modulus_ratio;
  });
  const auto [y_lo, y_hi] = std::minmax_element(
      cells.begin(), cells.end(), [](auto& a, auto& b) { return a.length_ratio < b.length_ratio; });
  auto half_spacing = [](double span, double fallback) {
    return span > 0.0 ? span / (2.0 * (kMapCells - 1)) : fallback;
  };
  const double dx =
      half_spacing(std::log10(x_hi->modulus_ratio / x_lo->modulus_ratio), 0.5);  // decades
  const double dy = half_spacing(y_hi->length_ratio - y_lo->length_ratio, 0.05);
  plot.series = {Series{.title = "use " + model_label(ImpactModel::ccm) + " at " + at,
                        .style = SeriesStyle::cells,
                        .cell_dx = dx,
                        .cell_dy = dy,
                        .color = 0},
                 Series{.title = "use " + model_label(ImpactModel::rigid) + " at " + at,
                        .style = SeriesStyle::cells,
                        .cell_dx = dx,
                        .cell_dy = dy,
                        .color = 1}};
  Series unreliable{.title = "unreliable answer (CCM or rigid) at " + at +
                             ": leave-one-out error exceeds the decision margin",
                    .style = SeriesStyle::points,
                    .color = 2};
  for (const MapCell& c : cells) {
    Series& s = plot.series[c.model == ImpactModel::ccm ? 0 : 1];
    s.x.push_back(c.modulus_ratio);
    s.y.push_back(c.length_ratio);
    if (!c.reliable) {
      unreliable.x.push_back(c.modulus_ratio);
      unreliable.y.push_back(c.length_ratio);
    }
  }
  if (!unreliable.empty()) plot.series.push_back(std::move(unreliable));
  add_measured_points(data, axes, ke, max_error, at, plot);
  return make_figure(
      fmt::format("fig-recommendation-ke-{:g}{}", ke, group_id(axes)),
      fmt::format("Model recommended at {} by the rule (rigid where all three predicted "
                  "final-state errors, eqs. 2.37-2.39, are within {:g} and RTR > 1; CCM "
                  "elsewhere) on the fitted surfaces; {}x{} cells over the studied range; dots "
                  "mark cells whose answer is unreliable; the measured grid points show the "
                  "rule on their measured values.",
                  at, max_error, kMapCells, kMapCells),
      std::move(plot));
}

}  // namespace

std::vector<MapCell> recommendation_cells(const study::StudyFits& fits,
                                          std::span<const study::PointMetrics> measured,
                                          const study::AxisLevels& axes, double kinetic_energy,
                                          double max_error) {
  const auto* range_fit = fits.find(study::Metric::final_kinetic_energy, kinetic_energy, axes);
  if (range_fit == nullptr) return {};
  const study::SurfaceFit& range = range_fit->fit;
  std::vector<MapCell> cells;
  for (int i = 0; i < kMapCells; ++i)
    for (int j = 0; j < kMapCells; ++j) {
      const double x = range.x_min + (range.x_max - range.x_min) * i / (kMapCells - 1);
      const double y = range.y_min + (range.y_max - range.y_min) * j / (kMapCells - 1);
      const double er = std::pow(10.0, x);
      study::RecommendQuery query{er, y, kinetic_energy, axes, max_error};
      const auto r = study::recommend(fits, measured, query);
      cells.push_back({er, y, r.model, r.reliability.reliable});
    }
  return cells;
}

RecommendationMaps recommendation_maps(const ReportData& data, double max_error) {
  RecommendationMaps maps;
  for (const study::AxisLevels& axes : data.fits.axis_groups())
    for (double ke : data.fits.kinetic_energy_levels(axes)) {
      try {
        if (auto f = map_figure(data, axes, ke, max_error)) maps.figures.push_back(std::move(*f));
      } catch (const std::runtime_error& e) {  // the fits lack a metric the decision needs
        maps.notes.push_back(
            fmt::format("No map at KE {:g} J{}: {}", ke, group_title(axes), e.what()));
      }
    }
  if (maps.figures.empty())
    maps.notes.push_back(
        "No map: the study has no fitted final-state error surface (no usable point).");
  return maps;
}

}  // namespace ccm::reports
