// The symmetric 3-point triangle rule of degree 2 (Strang & Fix) on which the penalty models
// place their springs (rigid_sphere_penalty.hpp explains why 3 points): point k has the
// barycentric coordinate kQuadratureNear at the triangle's node k and kQuadratureFar at the other
// two. kQuadratureNear is 1 - 2 kQuadratureFar so that the three shape functions at a point sum to
// 1 as closely as floating point allows (the force handed to the nodes is the force applied).
#pragma once

#include <array>
#include <cstddef>

namespace ccm {

inline constexpr double kQuadratureFar = 1.0 / 6.0;
inline constexpr double kQuadratureNear = 1.0 - 2.0 * kQuadratureFar;

// Barycentric weights (N_0, N_1, N_2) of quadrature point k.
constexpr std::array<double, 3> surface_point_weights(int k) {
  std::array<double, 3> N{kQuadratureFar, kQuadratureFar, kQuadratureFar};
  N[static_cast<std::size_t>(k)] = kQuadratureNear;
  return N;
}

}  // namespace ccm
