// Errors between the CCM and the rigid-body history of one artifact quantity (thesis 2.8).
// Both histories must be sampled at the same times (same length, sample i <-> sample i).
#pragma once

#include <span>

namespace ccm::study {

// Cumulative error of eqs. 2.34-2.36, read as a time average so that it does not depend on how
// often the histories are sampled (docs/metrics.md):
//   e = <(c - r)^2> / ((<c> + <r>) / 2),   <g> = (1 / (t_N - t_0)) int_{t_0}^{t_N} g(t) dt
// each integral by the trapezoidal rule over the sample times. The thesis prints
// sum_i (c_i - r_i)^2 over its output samples: at a fixed output rate f that sum is
// f x int (c - r)^2 dt, so its size follows f; dividing by the samples' span makes it the time
// average (at a uniform rate, (sum_i g_i) / N -> <g>). The printed formula takes no root (the
// text says "root sum of squares"): we take none. (2.36 prints KE_max-bar in the denominator
// while its text defines the mean of the average kinetic energy: we use the mean of the series
// given.) Zero when both series are identically zero. Throws std::invalid_argument on empty or
// mismatched series, fewer than two samples, or times that do not increase; std::domain_error
// when the means cancel with a non-zero difference.
double cumulative_error(std::span<const double> time, std::span<const double> ccm,
                        std::span<const double> rigid);

// The same for histories sampled at a uniform interval (the time average does not depend on
// the interval's size, so none is needed): sample i at time i.
double cumulative_error(std::span<const double> ccm, std::span<const double> rigid);

// Final-state error (eqs. 2.37-2.39):
//   e = |c(t_f) - r(t_f)| / max(max_i |c_i|, max_i |r_i|)
// with t_f the last sample. Zero when both series are identically zero.
double final_state_error(std::span<const double> ccm, std::span<const double> rigid);

}  // namespace ccm::study
