// The central-difference stable step of one tet in its current configuration: the scalar form of
// the bound the element kernel applies to every element each step (internal_force.cpp,
// docs/time-step.md, "The current state: shape and stiffness"):
//   dt_e = h_e sqrt(rho0 / M),   h_e = characteristic_length(Ds)   (tet4.hpp),
//   M = lambda (1 + 2 |ln J|) + mu (2 + max(tr C - 3, 0))   Neo-Hookean (the tangent in
//   compression), M = lambda + 2 mu                                        linear elastic
//   (reference moduli).
// The kernel writes the same as dt^2 = (lambda + 2 mu) / (c_d^2 y), y = sum_f |n_f|^2 M / det^2.
#pragma once

#include <algorithm>
#include <cmath>

#include "engine/core/types.hpp"
#include "engine/element/tet4.hpp"
#include "engine/material/material.hpp"

namespace ccm {

// Ds: the current edge matrix (edge_matrix of the four nodes), Dm_inv: the reference one's
// inverse; lame: the body's full moduli. 0 for an inverted or degenerate tet.
inline double element_stable_dt(MaterialModel model, const Mat3& Ds, const Mat3& Dm_inv,
                                const Lame& lame, double rho0) {
  const Mat3 F = Ds * Dm_inv;
  const double J = F.determinant();
  if (!(J > 0.0)) return 0.0;
  double M = lame.lambda + 2.0 * lame.mu;
  if (model == MaterialModel::neo_hookean) {
    const double stretch = std::max((F.transpose() * F).trace() - 3.0, 0.0);
    M = lame.lambda * (1.0 + 2.0 * std::abs(std::log(J))) + lame.mu * (2.0 + stretch);
  }
  return characteristic_length(Ds) * std::sqrt(rho0 / M);
}

}  // namespace ccm
