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

std::optional<Figure> map_figure(const study::StudyFits& fits, double ke, double max_error) {
  const auto cells = recommendation_cells(fits, ke, max_error);
  if (cells.empty()) return std::nullopt;
  PlotSpec plot{.title = fmt::format("Recommended model, KE {:g} J, max error {:g}", ke, max_error),
                .x_label = "ER = E_impactor / E_artifact [-]",
                .y_label = "RLS = D_impactor / L_artifact [-]",
                .log_x = true};
  const std::string at = fmt::format(" at KE {:g} J", ke);
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
  plot.series = {Series{.title = "use " + model_label(ImpactModel::ccm) + at,
                        .style = SeriesStyle::cells,
                        .cell_dx = dx,
                        .cell_dy = dy,
                        .color = 0},
                 Series{.title = "use " + model_label(ImpactModel::rigid) + at,
                        .style = SeriesStyle::cells,
                        .cell_dx = dx,
                        .cell_dy = dy,
                        .color = 1}};
  for (const MapCell& c : cells) {
    Series& s = plot.series[c.model == ImpactModel::ccm ? 0 : 1];
    s.x.push_back(c.modulus_ratio);
    s.y.push_back(c.length_ratio);
  }
  return make_figure(
      fmt::format("fig-recommendation-ke-{:g}", ke),
      fmt::format("Model recommended at KE {:g} J: rigid where all three predicted final-state "
                  "errors (fitted surfaces, eqs. 2.37-2.39) are below {:g}, CCM elsewhere; "
                  "{}x{} cells over the studied range.",
                  ke, max_error, kMapCells, kMapCells),
      std::move(plot));
}

}  // namespace

std::vector<MapCell> recommendation_cells(const study::StudyFits& fits, double kinetic_energy,
                                          double max_error) {
  const auto* range_fit = fits.find(study::Metric::final_kinetic_energy, kinetic_energy);
  if (range_fit == nullptr) return {};
  const study::SurfaceFit& range = range_fit->fit;
  std::vector<MapCell> cells;
  for (int i = 0; i < kMapCells; ++i)
    for (int j = 0; j < kMapCells; ++j) {
      const double x = range.x_min + (range.x_max - range.x_min) * i / (kMapCells - 1);
      const double y = range.y_min + (range.y_max - range.y_min) * j / (kMapCells - 1);
      const double er = std::pow(10.0, x);
      study::RecommendQuery query;
      query.modulus_ratio = er;
      query.length_ratio = y;
      query.kinetic_energy = kinetic_energy;
      query.max_error = max_error;
      const auto r = study::recommend(fits, query);
      cells.push_back({er, y, r.model});
    }
  return cells;
}

Section recommendation_section(const ReportData& data, double max_error) {
  Section s{.id = "recommendation", .title = "Recommendation map"};
  s.paragraphs.push_back(fmt::format(
      "Which impactor model to use over the studied (ER, RLS) plane at each KE level, at the "
      "error threshold --max-error {:g} (as `ccm recommend --max-error`).",
      max_error));
  for (double ke : data.fits.kinetic_energy_levels()) {
    try {
      if (auto f = map_figure(data.fits, ke, max_error)) s.figures.push_back(std::move(*f));
    } catch (const std::runtime_error& e) {  // the fits lack a metric the decision needs
      s.paragraphs.push_back(fmt::format("No map at KE {:g} J: {}", ke, e.what()));
    }
  }
  if (s.figures.empty())
    s.paragraphs.push_back(
        "No map: the study has no fitted final-state error surface (no usable point).");
  return s;
}

}  // namespace ccm::reports
