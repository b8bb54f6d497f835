// Richardson extrapolation of a quantity computed on three meshes, the reference of a convergence
// study where no closed form holds (docs/contact-persistent.md, "The converged solution at
// +-5 m/s"). The meshes' sizes h1 > h2 > h3 need not share one ratio. With f(h) = f0 + C h^p,
// the observed order p solves
//     (f1 - f2) / (f2 - f3) = (h1^p - h2^p) / (h2^p - h3^p)                          (R.1)
// (the generalised Richardson extrapolation; Celik et al., J. Fluids Eng. 130 (2008) 078001,
// eqs. 3a-3c, solved here by bisection instead of their fixed point), and the limit is
//     f0 = f3 + (f3 - f2) / ((h2 / h3)^p - 1)                                           (R.2)
// (their eq. 4). The right side of (R.1) grows with p from ln(h1/h2) / ln(h2/h3) at p -> 0, so
// there is a root only when the three values converge monotonically, with that ratio above the
// bound; otherwise there is no observed order (oscillating or not yet asymptotic) and no limit.
#pragma once

#include <cmath>
#include <optional>

namespace ccm::test {

struct Richardson {
  double order;  // observed p
  double limit;  // f0, the extrapolated value at h -> 0
};

inline std::optional<Richardson> richardson(double h1, double f1, double h2, double f2, double h3,
                                            double f3) {
  if (!(h1 > h2 && h2 > h3 && h3 > 0.0) || f2 == f3) return std::nullopt;
  const double ratio = (f1 - f2) / (f2 - f3);
  const auto rhs = [&](double p) {
    return (std::pow(h1, p) - std::pow(h2, p)) / (std::pow(h2, p) - std::pow(h3, p));
  };
  double lo = 1e-3, hi = 20.0;  // orders outside are not a convergence study's
  if (!(ratio > rhs(lo) && ratio < rhs(hi))) return std::nullopt;
  for (int k = 0; k < 200 && hi - lo > 1e-12; ++k) {
    const double mid = 0.5 * (lo + hi);
    (rhs(mid) < ratio ? lo : hi) = mid;
  }
  const double p = 0.5 * (lo + hi);
  return Richardson{p, f3 + (f3 - f2) / (std::pow(h2 / h3, p) - 1.0)};
}

}  // namespace ccm::test
