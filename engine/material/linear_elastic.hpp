// Small-strain linear elasticity (thesis eq. 2.1). P is taken equal to sigma, which is
// consistent only for small displacement gradients; it is not rotation invariant.
#pragma once

#include "engine/core/types.hpp"
#include "engine/material/material.hpp"

namespace ccm::linear_elastic {

// eps = sym(F - I)
inline Mat3 small_strain(const Mat3& F) {
  const Mat3 H = F - Mat3::Identity();
  return 0.5 * (H + H.transpose());
}

// sigma = lambda tr(eps) I + 2 mu eps   (eq. 2.1)
inline Mat3 stress(const Mat3& F, const Lame& l) {
  const Mat3 eps = small_strain(F);
  return l.lambda * eps.trace() * Mat3::Identity() + 2.0 * l.mu * eps;
}

// W = lambda/2 tr(eps)^2 + mu eps:eps
inline double strain_energy_density(const Mat3& F, const Lame& l) {
  const Mat3 eps = small_strain(F);
  const double tr = eps.trace();
  return 0.5 * l.lambda * tr * tr + l.mu * eps.squaredNorm();
}

}  // namespace ccm::linear_elastic
