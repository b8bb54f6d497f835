// The ISO/TS 18571 objective rating of a comparison curve (the simulation) against a reference
// curve (the test), both sampled at the same instants: four scores in [0, 1] combined into one
// rating, and its grade (docs/correlation.md, equations R.1–R.6; the 2024 edition's procedure, as
// TU Graz's public implementation of it computes it, with the standard's default parameters):
//
//   corridor   Z   = mean over samples of 1 inside the inner corridor (|C - T| < a0 max|T|),
//                    0 outside the outer one (|C - T| > b0 max|T|), else
//                    ((b0 max|T| - |C - T|) / ((b0 - a0) max|T|))^kz                       (R.1)
//   phase      E_P = 1 at no shift, 0 at a shift of eps_P N samples or more, else
//                    ((eps_P N - n) / (eps_P N))^kp, n the shift (in samples) that maximises
//                    the Pearson correlation of the overlapping parts                         (R.2)
//   magnitude  E_M = (eps_M - e_M) / eps_M clipped to [0, 1]^km, e_M = sum |C_w - T_w| / sum |T_w|
//                    of the shifted curves warped by dynamic time warping (band 10 % of N)   (R.3)
//   slope      E_S = (eps_S - e_S) / eps_S clipped, e_S = sum |C' - T'| / sum |T'| of the shifted
//                    curves' derivatives, central differences averaged over 9 samples        (R.4)
//   rating     R   = 0.4 Z + 0.2 E_P + 0.2 E_M + 0.2 E_S                                     (R.5)
//   grade      excellent R > 0.94, good R > 0.80, fair R > 0.58, else poor                   (R.6)
#pragma once

#include <span>
#include <string_view>

namespace ccm::correlate {

enum class RatingGrade { excellent, good, fair, poor };

struct RatingParameters {
  double inner_corridor = 0.05;      // a0: inner half-width over max |T|
  double outer_corridor = 0.50;      // b0: outer half-width over max |T|
  double corridor_exponent = 2;      // kz
  double max_shift = 0.20;           // eps_P: the largest shift scored, over N
  double phase_exponent = 1;         // kp
  double max_magnitude_error = 0.5;  // eps_M
  double magnitude_exponent = 1;     // km
  double max_slope_error = 2.0;      // eps_S
  double dtw_band = 0.10;            // the warping band's half-width over N
};

struct CurveRating {
  double corridor = 0.0;   // Z, R.1
  double phase = 0.0;      // E_P, R.2
  double magnitude = 0.0;  // E_M, R.3
  double slope = 0.0;      // E_S, R.4
  double overall = 0.0;    // R, R.5
  RatingGrade grade = RatingGrade::poor;
  // What the scores came from: the shift in samples (positive: the comparison lags the
  // reference), the correlation it reached, and the magnitude and slope errors.
  long shift_samples = 0;
  double shift_correlation = 0.0;
  double magnitude_error = 0.0;
  double slope_error = 0.0;
};

// The rating of `comparison` against `reference`, sampled every `sample_interval` seconds at the
// same instants. Throws std::invalid_argument unless both have the same length of at least 10
// samples, every value is finite, the reference is not zero everywhere and sample_interval > 0.
CurveRating iso18571_rating(std::span<const double> reference, std::span<const double> comparison,
                            double sample_interval, const RatingParameters& parameters = {});

// R.6.
RatingGrade rating_grade(double overall);
std::string_view grade_name(RatingGrade grade);

}  // namespace ccm::correlate
