// Mass, centre of mass and inertia tensor of a body of uniform density meshed by linear tets,
// exact for the meshed volume (a tet integrates polynomials of degree two exactly):
//   m = rho sum_e V_e,   c = (1/m) rho sum_e V_e xbar_e,
//   C = rho sum_e V_e/20 (sum_a x_a x_a^T + s s^T),  s = sum_a x_a     (docs/rigid-bodies.md, RB.1)
//   I_c = tr(C_c) 1 - C_c,  C_c = C - m c c^T                             (RB.2)
// with x_a the tet's four vertices. The principal frame diagonalises I_c.
#pragma once

#include <vector>

#include "engine/core/types.hpp"
#include "engine/mesh/tet_mesh.hpp"

namespace ccm {

struct MassProperties {
  double mass = 0.0;            // [kg]
  Vec3 center = Vec3::Zero();   // centre of mass [m]
  Mat3 inertia = Mat3::Zero();  // about the centre of mass, world axes [kg m^2]
};

// Over the tets of `tets` (node ids into x) with density rho. Throws std::invalid_argument when
// the volume is not positive or rho is not.
MassProperties tet_mass_properties(const std::vector<Tet>& tets, const std::vector<Vec3>& x,
                                   double rho);

// The inertia tensor of a given mass distribution, moved from its centre of mass to a point at
// offset d from it (parallel axis theorem): I_d = I_c + m (|d|^2 1 - d d^T).   (RB.3)
Mat3 inertia_about(const MassProperties& p, const Vec3& d);

}  // namespace ccm
