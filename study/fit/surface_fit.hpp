// A polynomial surface with its degree chosen by leave-one-out cross-validation, and its
// goodness-of-fit figures (thesis App. B; docs/equations.md "Surface fits").
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "study/fit/polynomial_surface.hpp"

namespace ccm::study {

struct SurfaceFit {
  PolynomialSurface surface;
  double r_squared = 0.0;  // 1 - SS_res / SS_tot on the samples (1 when SS_tot = SS_res = 0)
  double loo_rmse = 0.0;   // leave-one-out root-mean-square prediction error
  std::vector<SurfaceSample> samples;                         // the points used
  double x_min = 0.0, x_max = 0.0, y_min = 0.0, y_max = 0.0;  // their range
};

struct FitOptions {
  int max_degree_x = 3;
  int max_degree_y = 2;  // with 3 RLS values a degree above 2 cannot be determined
};

// Leave-one-out RMSE of degree `degree`: each sample predicted by the surface fitted to all
// others. Empty when any of those fits is rank deficient (the left-out point carries
// information no other point has, so the degree is not supported by the data).
std::optional<double> leave_one_out_rmse(std::span<const SurfaceSample> samples,
                                         SurfaceDegree degree);

// Fits every degree up to the options' maxima, the constant (0, 0) included, that leaves at
// least one residual degree of freedom and whose leave-one-out fits are all full rank, and
// keeps the one with the smallest leave-one-out RMSE. Among degrees whose LOO RMSE is within
// 1e-9 of the data's scale (their range, or their size when all equal) of that best (exact
// data: all rounding), the one with the fewest terms is kept. Empty when no degree
// qualifies (fewer than 2 samples).
std::optional<SurfaceFit> fit_surface(std::span<const SurfaceSample> samples,
                                      const FitOptions& options = {});

// R^2 = 1 - SS_res / SS_tot of `surface` on `samples`.
double coefficient_of_determination(const PolynomialSurface& surface,
                                    std::span<const SurfaceSample> samples);

}  // namespace ccm::study
