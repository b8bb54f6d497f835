// GCC 12 reports -Wmaybe-uninitialized inside Eigen's AVX-512 matrix-vector product (a false
// positive on _mm512_undefined_pd, GCC bug 105593) when built with -march=native on an AVX-512
// machine. The warning is emitted after inlining, so it is silenced for this file only,
// before the first include (GCC applies the pragma by source location).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include "study/fit/polynomial_surface.hpp"

#include <Eigen/QR>
#include <cmath>

namespace ccm::study {

namespace {

// Row of the design matrix: x^i y^j in the i-major term order.
Eigen::RowVectorXd basis_row(double x, double y, SurfaceDegree degree) {
  Eigen::RowVectorXd row(degree.n_terms());
  int k = 0;
  for (int i = 0; i <= degree.x; ++i)
    for (int j = 0; j <= degree.y; ++j) row(k++) = std::pow(x, i) * std::pow(y, j);
  return row;
}

}  // namespace

double PolynomialSurface::operator()(double x, double y) const {
  double z = 0.0;
  for (const SurfaceTerm& t : terms)
    z += t.coefficient * std::pow(x, t.power_x) * std::pow(y, t.power_y);
  return z;
}

std::optional<PolynomialSurface> least_squares_surface(std::span<const SurfaceSample> samples,
                                                       SurfaceDegree degree) {
  const Eigen::Index n_terms = degree.n_terms();
  if (static_cast<Eigen::Index>(samples.size()) < n_terms) return std::nullopt;
  Eigen::MatrixXd design(static_cast<Eigen::Index>(samples.size()), n_terms);
  Eigen::VectorXd z(design.rows());
  for (Eigen::Index r = 0; r < design.rows(); ++r) {
    const SurfaceSample& s = samples[static_cast<std::size_t>(r)];
    design.row(r) = basis_row(s.x, s.y, degree);
    z(r) = s.z;
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(design);
  qr.setThreshold(1e-10);
  if (qr.rank() < n_terms) return std::nullopt;
  const Eigen::VectorXd c = qr.solve(z);

  PolynomialSurface surface;
  surface.degree = degree;
  int k = 0;
  for (int i = 0; i <= degree.x; ++i)
    for (int j = 0; j <= degree.y; ++j) surface.terms.push_back({i, j, c(k++)});
  return surface;
}

}  // namespace ccm::study
