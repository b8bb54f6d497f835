// The per-point quantities the study fits and recommends on, with a name table.
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include "study/metrics/point_metrics.hpp"

namespace ccm::study {

enum class Metric {
  w_u_mean,  // weighting functions, final-state error / RTR
  w_u_max,
  w_kinetic_energy,
  runtime_ratio,  // RTR (eq. 2.40)
  final_u_mean,   // final-state errors (eqs. 2.37-2.39)
  final_u_max,
  final_kinetic_energy,
  cumulative_u_mean,  // cumulative errors (eqs. 2.34-2.36)
  cumulative_u_max,
  cumulative_kinetic_energy,
};

inline constexpr std::array<Metric, 10> kAllMetrics = {Metric::w_u_mean,
                                                       Metric::w_u_max,
                                                       Metric::w_kinetic_energy,
                                                       Metric::runtime_ratio,
                                                       Metric::final_u_mean,
                                                       Metric::final_u_max,
                                                       Metric::final_kinetic_energy,
                                                       Metric::cumulative_u_mean,
                                                       Metric::cumulative_u_max,
                                                       Metric::cumulative_kinetic_energy};

std::string_view to_string(Metric metric);
std::optional<Metric> metric_from_string(std::string_view name);

// The value of `metric` at a usable point.
double metric_value(const PointMetrics& point, Metric metric);

}  // namespace ccm::study
