#include "study/metrics/metric.hpp"

#include <algorithm>
#include <cmath>

namespace ccm::study {

std::string_view to_string(Metric metric) {
  switch (metric) {
    case Metric::log10_w_u_mean:
      return "log10_w_u_mean";
    case Metric::log10_w_u_max:
      return "log10_w_u_max";
    case Metric::log10_w_kinetic_energy:
      return "log10_w_kinetic_energy";
    case Metric::log10_runtime_ratio:
      return "log10_rtr";
    case Metric::final_u_mean:
      return "final_u_mean";
    case Metric::final_u_max:
      return "final_u_max";
    case Metric::final_kinetic_energy:
      return "final_kinetic_energy";
    case Metric::cumulative_u_mean:
      return "cumulative_u_mean";
    case Metric::cumulative_u_max:
      return "cumulative_u_max";
    case Metric::cumulative_kinetic_energy:
      return "cumulative_kinetic_energy";
    case Metric::log10_nt_ccm:
      return "log10_nt_ccm";
    case Metric::log10_nt_rigid:
      return "log10_nt_rigid";
  }
  return "unknown";
}

std::optional<Metric> metric_from_string(std::string_view name) {
  for (const Metric m : kAllMetrics)
    if (to_string(m) == name) return m;
  return std::nullopt;
}

bool fitted_in_log10(Metric metric) {
  switch (metric) {
    case Metric::log10_w_u_mean:
    case Metric::log10_w_u_max:
    case Metric::log10_w_kinetic_energy:
    case Metric::log10_runtime_ratio:
    case Metric::log10_nt_ccm:
    case Metric::log10_nt_rigid:
      return true;
    default:
      return false;
  }
}

namespace {

double log10_weight(double w) { return std::log10(std::max(w, kWeightFloor)); }

}  // namespace

double metric_value(const PointMetrics& p, Metric metric) {
  switch (metric) {
    case Metric::log10_w_u_mean:
      return log10_weight(p.weighting.u_mean);
    case Metric::log10_w_u_max:
      return log10_weight(p.weighting.u_max);
    case Metric::log10_w_kinetic_energy:
      return log10_weight(p.weighting.kinetic_energy);
    case Metric::log10_runtime_ratio:
      return std::log10(p.runtime_ratio);
    case Metric::final_u_mean:
      return p.final_state.u_mean;
    case Metric::final_u_max:
      return p.final_state.u_max;
    case Metric::final_kinetic_energy:
      return p.final_state.kinetic_energy;
    case Metric::cumulative_u_mean:
      return p.cumulative.u_mean;
    case Metric::cumulative_u_max:
      return p.cumulative.u_max;
    case Metric::cumulative_kinetic_energy:
      return p.cumulative.kinetic_energy;
    case Metric::log10_nt_ccm:
      return std::log10(p.ccm.normalised_runtime);
    case Metric::log10_nt_rigid:
      return std::log10(p.rigid.normalised_runtime);
  }
  return 0.0;
}

}  // namespace ccm::study
