// Errors between the CCM and the rigid-body history of one artifact quantity (thesis 2.8).
// Both histories must be sampled at the same times (same length, sample i <-> sample i).
#pragma once

#include <span>

namespace ccm::study {

// Cumulative error, exactly as printed in the thesis (eqs. 2.34-2.36):
//   e = sum_i (c_i - r_i)^2 / ((mean_i c_i + mean_i r_i) / 2)
// The text calls it a "root sum of squares" but the printed formula takes no root; we follow
// the formula. (2.36 prints KE_max-bar in the denominator, while its text defines the mean of
// the average kinetic energy over all iterations: we use the mean of the series given.)
// Zero when both series are identically zero; throws std::domain_error when the means cancel
// with a non-zero sum, and std::invalid_argument on empty or mismatched series.
double cumulative_error(std::span<const double> ccm, std::span<const double> rigid);

// Final-state error (eqs. 2.37-2.39):
//   e = |c(t_f) - r(t_f)| / max(max_i |c_i|, max_i |r_i|)
// with t_f the last sample. Zero when both series are identically zero.
double final_state_error(std::span<const double> ccm, std::span<const double> rigid);

}  // namespace ccm::study
