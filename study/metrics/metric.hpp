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
  // log10 of the normalised runtimes NT = AIR / ISTS (eqs. 2.41-2.42; surfaces of Fig. 2-28).
  // Fitted in log10: NT ~ 1 / ISTS grows like sqrt(ER) (ISTS ~ sqrt(rho / E)), which is linear in
  // x = log10 ER, while a polynomial in NT itself swings between the ER levels (the cubic through
  // 2 sqrt(ER) at ER = 1, 1e2, 1e4, 1e6 is negative near ER = 10^2.5).
  log10_nt_ccm,
  log10_nt_rigid,
};

inline constexpr std::array<Metric, 12> kAllMetrics = {Metric::w_u_mean,
                                                       Metric::w_u_max,
                                                       Metric::w_kinetic_energy,
                                                       Metric::runtime_ratio,
                                                       Metric::final_u_mean,
                                                       Metric::final_u_max,
                                                       Metric::final_kinetic_energy,
                                                       Metric::cumulative_u_mean,
                                                       Metric::cumulative_u_max,
                                                       Metric::cumulative_kinetic_energy,
                                                       Metric::log10_nt_ccm,
                                                       Metric::log10_nt_rigid};

std::string_view to_string(Metric metric);
std::optional<Metric> metric_from_string(std::string_view name);

// The value of `metric` at a usable point.
double metric_value(const PointMetrics& point, Metric metric);

}  // namespace ccm::study
