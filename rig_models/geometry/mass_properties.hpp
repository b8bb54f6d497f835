// Mass properties of meshed parts as the integrator sees them (lumped masses rho V_e / 4 on
// each node of each tet), and the densities that give parts a required mass and moment of
// inertia: the thesis's "dynamically similar, simplified CAD" whose internal components' material
// properties were tuned until the mass properties matched the full model (3.3.1).
#pragma once

#include <vector>

#include "engine/mesh/tet_mesh.hpp"

namespace ccm::rig {

// One region of a TetMesh at unit density: volume V = sum V_e [m^3], moment of inertia about
// the axis I = sum_e V_e / 4 sum_a |r_perp(X_a)|^2 [m^5], and first moment sum_e V_e / 4 sum_a
// X_a [m^4] (centre of mass = first moment / V).
struct UnitMass {
  double volume = 0.0;
  double inertia = 0.0;
  Vec3 first_moment = Vec3::Zero();
};

// Per region (index as mesh.region_names); the axis through `point` along `direction`.
std::vector<UnitMass> unit_mass_properties(const TetMesh& mesh, const Vec3& point,
                                           const Vec3& direction);

// The two densities rho_a, rho_b > 0 that give parts a and b, beside a part of fixed mass
// m_fixed and inertia I_fixed, the total mass M and inertia J:
//   rho_a V_a + rho_b V_b = M - m_fixed,  rho_a I_a + rho_b I_b = J - I_fixed.
// Throws std::invalid_argument, with the numbers, when the solution is not positive (the
// geometry cannot carry that mass and inertia).
struct DensityPair {
  double rho_a = 0.0;
  double rho_b = 0.0;
};
DensityPair densities_for(const UnitMass& a, const UnitMass& b, double M, double J, double m_fixed,
                          double I_fixed);

}  // namespace ccm::rig
