// Polynomial surfaces z(x, y) = sum_{i<=p, j<=q} c_ij x^i y^j fitted by least squares
// (thesis App. B fits the weighting functions over x = log10 ER, y = RLS).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>
#include <vector>

namespace ccm::study {

// Degrees in x (log10 ER) and y (RLS); the basis is the tensor product x^i y^j, i <= x, j <= y.
struct SurfaceDegree {
  int x = 0;
  int y = 0;
  int n_terms() const { return (x + 1) * (y + 1); }
  bool operator==(const SurfaceDegree&) const = default;
};

// One term c x^i y^j.
struct SurfaceTerm {
  int power_x = 0;
  int power_y = 0;
  double coefficient = 0.0;
};

struct PolynomialSurface {
  SurfaceDegree degree;
  std::vector<SurfaceTerm> terms;  // i-major: (0,0), (0,1), ..., (1,0), ...
  double operator()(double x, double y) const;
};

// One data point of a fit; `id` identifies it to the caller (the grid point's index).
struct SurfaceSample {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
  int id = 0;
};

// Least-squares surface of the given degree (Eigen column-pivoting QR). Empty when the design
// matrix is rank deficient (numerical rank below the number of terms at a relative pivot
// threshold of 1e-10), i.e. when the samples cannot determine every coefficient: for instance
// a degree 2 in y with only two distinct y values.
std::optional<PolynomialSurface> least_squares_surface(std::span<const SurfaceSample> samples,
                                                       SurfaceDegree degree);

}  // namespace ccm::study
