// The per-point quantities the study fits and recommends on, with a name table.
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include "records/point_metrics.hpp"

namespace ccm::study {

// Quantities that span decades (runtimes, their ratio, the weighting functions) are fitted in
// log10: RTR ~ NT_ccm / NT_rigid and NT ~ 1 / ISTS grow like a power of ER (ISTS ~ sqrt(rho / E)),
// which is linear in x = log10 ER, while a polynomial in the value itself swings between the ER
// levels (the cubic through 2 sqrt(ER) at ER = 1, 1e2, 1e4, 1e6 is negative near ER = 10^2.5),
// and a prediction 10^f is never negative. The errors are fitted as they are (they lie in
// [0, ~1] and may be 0); their predictions are clamped to the range observed
// (study/recommend/prediction.hpp).
enum class Metric {
  log10_w_u_mean,  // log10 of the weighting functions w = final-state error / RTR
  log10_w_u_max,   // (thesis 2.8, Fig. 2-29), floored at kWeightFloor
  log10_w_kinetic_energy,
  log10_runtime_ratio,  // log10 RTR (eq. 2.40)
  final_u_mean,         // final-state errors (eqs. 2.37-2.39)
  final_u_max,
  final_kinetic_energy,
  cumulative_u_mean,  // cumulative errors (eqs. 2.34-2.36)
  cumulative_u_max,
  cumulative_kinetic_energy,
  log10_nt_ccm,  // log10 of the normalised runtimes NT = AIR / ISTS (eqs. 2.41-2.42; Fig. 2-28)
  log10_nt_rigid,
};

inline constexpr std::array<Metric, 12> kAllMetrics = {
    Metric::log10_w_u_mean,         Metric::log10_w_u_max,
    Metric::log10_w_kinetic_energy, Metric::log10_runtime_ratio,
    Metric::final_u_mean,           Metric::final_u_max,
    Metric::final_kinetic_energy,   Metric::cumulative_u_mean,
    Metric::cumulative_u_max,       Metric::cumulative_kinetic_energy,
    Metric::log10_nt_ccm,           Metric::log10_nt_rigid};

// w below this is taken as this before log10 (w = 0 where the rigid model is exact): 1e-6 is a
// final-state error of one part in a million at RTR 1, far below any decision threshold.
inline constexpr double kWeightFloor = 1e-6;

std::string_view to_string(Metric metric);
std::optional<Metric> metric_from_string(std::string_view name);

// True for the metrics stored and fitted as log10 of the quantity.
bool fitted_in_log10(Metric metric);

// The value of `metric` at a usable point (log10 of the quantity where fitted_in_log10).
double metric_value(const PointMetrics& point, Metric metric);

}  // namespace ccm::study
