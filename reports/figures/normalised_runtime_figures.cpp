#include "reports/figures/normalised_runtime_figures.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>

#include "reports/figures/labels.hpp"
#include "reports/figures/surface_series.hpp"

namespace ccm::reports {
namespace {

using study::ImpactModel;
using study::Metric;

struct ModelNt {
  ImpactModel model;
  Metric metric;
  const char* symbol;  // in the caption's equation
};

constexpr std::array<ModelNt, 2> kModels = {
    ModelNt{ImpactModel::ccm, Metric::log10_nt_ccm, "log10 NT_CCM"},
    ModelNt{ImpactModel::rigid, Metric::log10_nt_rigid, "log10 NT_rigid"}};

double ten_to(double z) { return std::pow(10.0, z); }

// The data points of one model's NT at one KE level (usable grid points only).
Series nt_samples(const ReportData& data, const ModelNt& m, double ke, const std::string& who) {
  Series s{.title = who + ": data", .color = static_cast<int>(m.model == ImpactModel::rigid)};
  for (const auto& pm : data.grid) {
    if (!pm.usable || pm.point.kinetic_energy != ke) continue;
    s.x.push_back(std::log10(pm.point.modulus_ratio));
    s.y.push_back(pm.point.length_ratio);
    s.z.push_back(m.model == ImpactModel::ccm ? pm.ccm.normalised_runtime
                                              : pm.rigid.normalised_runtime);
  }
  return s;
}

Figure nt_figure(const ReportData& data, double ke) {
  PlotSpec plot{.title = fmt::format("Normalised runtime NT, KE {:g} J", ke),
                .x_label = "log10 ER [-]",
                .y_label = "RLS [-]",
                .z_label = "NT = AIR / ISTS [s/s]",
                .three_d = true};
  std::string fits_text;
  for (const ModelNt& m : kModels) {
    const std::string who = fmt::format("{}, KE {:g} J", model_label(m.model), ke);
    const int color = static_cast<int>(m.model == ImpactModel::rigid);
    if (const study::MetricFit* f = data.fits.find(m.metric, ke)) {
      plot.series.push_back(surface_mesh(f->fit, who + ": fitted surface", color, &ten_to));
      fits_text += fmt::format(" {}: {}, {}.", model_label(m.model),
                               surface_equation(f->fit.surface, m.symbol), fit_quality(f->fit));
    } else {
      fits_text += fmt::format(
          " {}: no fitted surface stored (a store written before NT was "
          "fitted: `ccm study run` again fits it).",
          model_label(m.model));
    }
    plot.series.push_back(nt_samples(data, m, ke, who));
  }
  plot.log_z = spans_decades(all_values(plot, 2));
  return make_figure(fmt::format("fig-normalised-runtime-ke-{:g}", ke),
                     fmt::format("Normalised runtime NT = AIR / ISTS (eqs. 2.41-2.42) of both "
                                 "models at KE {:g} J, fitted surfaces and data (thesis Fig. "
                                 "2-28). The surfaces are fitted to log10 NT (NT grows like "
                                 "sqrt(ER)); x = log10 ER, y = RLS.{}",
                                 ke, fits_text),
                     std::move(plot));
}

}  // namespace

std::vector<Figure> normalised_runtime_figures(const ReportData& data) {
  std::vector<study::GridPoint> usable;
  for (const auto& m : data.grid)
    if (m.usable) usable.push_back(m.point);
  std::vector<Figure> out;
  for (double ke : kinetic_energy_levels(usable)) out.push_back(nt_figure(data, ke));
  return out;
}

}  // namespace ccm::reports
