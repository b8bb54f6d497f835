#include "reports/figures/labels.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace ccm::reports {

std::string model_label(study::ImpactModel model) {
  return model == study::ImpactModel::ccm ? "CCM (meshed sphere, DCR)"
                                          : "rigid (analytic sphere, penalty)";
}

std::string main_case_label(const study::GridPoint& p) {
  return fmt::format("ER {:g}, RLS {:g}, KE {:g} J", p.modulus_ratio, p.length_ratio,
                     p.kinetic_energy);
}

std::string case_label(const study::GridPoint& p) {
  std::string out = main_case_label(p);
  for (const auto& [name, value] : p.other_axes) out += fmt::format(", {} {:g}", name, value);
  return out;
}

std::string metric_label(study::Metric metric) {
  using study::Metric;
  switch (metric) {
    case Metric::log10_w_u_mean:
      return "log10 w, w = final-state error in u_mean / RTR [log10 -]";
    case Metric::log10_w_u_max:
      return "log10 w, w = final-state error in u_max / RTR [log10 -]";
    case Metric::log10_w_kinetic_energy:
      return "log10 w, w = final-state error in artifact KE / RTR [log10 -]";
    case Metric::log10_runtime_ratio:
      return "log10 RTR, RTR = TR_CCM / TR_rigid (measured) [log10 -]";
    case Metric::final_u_mean:
      return "final-state error in u_mean [-]";
    case Metric::final_u_max:
      return "final-state error in u_max [-]";
    case Metric::final_kinetic_energy:
      return "final-state error in artifact KE [-]";
    case Metric::cumulative_u_mean:
      return "cumulative error in u_mean [m]";
    case Metric::cumulative_u_max:
      return "cumulative error in u_max [m]";
    case Metric::cumulative_kinetic_energy:
      return "cumulative error in artifact KE [J]";
    case Metric::log10_nt_ccm:
      return "log10 NT_CCM, NT = AIR / ISTS [log10 s/s]";
    case Metric::log10_nt_rigid:
      return "log10 NT_rigid, NT = AIR / ISTS [log10 s/s]";
  }
  return std::string(study::to_string(metric));
}

std::vector<double> kinetic_energy_levels(const std::vector<study::GridPoint>& points) {
  std::vector<double> levels;
  for (const auto& p : points) levels.push_back(p.kinetic_energy);
  std::sort(levels.begin(), levels.end());
  levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
  return levels;
}

}  // namespace ccm::reports
