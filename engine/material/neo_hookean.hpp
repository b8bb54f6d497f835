// Compressible Neo-Hookean hyperelasticity (thesis eq. 2.2-2.3; Bonet & Wood, Nonlinear
// Continuum Mechanics for Finite Element Analysis, 2nd ed., eq. 6.28).
#pragma once

#include <Eigen/LU>  // determinant
#include <cmath>

#include "engine/core/types.hpp"
#include "engine/material/material.hpp"

namespace ccm::neo_hookean {

// W = lambda/2 (ln J)^2 - mu ln J + mu/2 (tr C - 3),  C = F^T F   (eq. 2.2)
inline double strain_energy_density(const Mat3& F, const Lame& l) {
  const double log_J = std::log(F.determinant());
  return 0.5 * l.lambda * log_J * log_J - l.mu * log_J + 0.5 * l.mu * (F.squaredNorm() - 3.0);
}

// P = mu (F - F^-T) + lambda ln(J) F^-T, with F^-T = cof(F) / J   (eq. 2.3 pushed to P = F S)
// cof_F and J are passed in because the element kernel already has them.
inline Mat3 first_piola(const Mat3& F, const Mat3& cof_F, double J, const Lame& l) {
  const Mat3 F_inv_T = cof_F / J;
  return l.mu * (F - F_inv_T) + (l.lambda * std::log(J)) * F_inv_T;
}

// Energy density from the quantities the kernel already has (tr C = |F|^2).
inline double strain_energy_density(const Mat3& F, double J, const Lame& l) {
  const double log_J = std::log(J);
  return 0.5 * l.lambda * log_J * log_J - l.mu * log_J + 0.5 * l.mu * (F.squaredNorm() - 3.0);
}

}  // namespace ccm::neo_hookean
