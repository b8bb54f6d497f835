// The linear 4-node tetrahedron: reference data precomputed once per element.
#pragma once

#include <Eigen/Geometry>  // cross
#include <Eigen/LU>        // determinant, inverse
#include <cmath>
#include <optional>

#include "engine/core/types.hpp"

namespace ccm {

// Dm = [X1-X0, X2-X0, X3-X0] (edge matrix of the reference tet). With Ds the same for the
// current tet, F = Ds Dm^-1 (= I + sum_a u_a (x) grad N_a), and the nodal forces of
// f_a = -V0 P grad N_a are the columns of H = -V0 P Dm^-T for a = 1..3, f_0 = -(f_1+f_2+f_3).
struct TetReference {
  Mat3 Dm_inv;
  double V0;
};

// Edge matrix [x1-x0, x2-x0, x3-x0].
inline Mat3 edge_matrix(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3) {
  Mat3 D;
  D.col(0) = x1 - x0;
  D.col(1) = x2 - x0;
  D.col(2) = x3 - x0;
  return D;
}

// Empty when the reference volume is not positive (degenerate or inverted tet).
inline std::optional<TetReference> make_tet_reference(const Vec3& X0, const Vec3& X1,
                                                      const Vec3& X2, const Vec3& X3) {
  const Mat3 Dm = edge_matrix(X0, X1, X2, X3);
  const double det = Dm.determinant();
  if (!(det > 0.0)) return std::nullopt;
  return TetReference{Dm.inverse(), det / 6.0};
}

// Characteristic length of the tet with edge matrix D for the stable step (docs/time-step.md):
//   h_e = 1 / sqrt(sum_a |grad N_a|^2) = det(D) / sqrt(sum_f |n_f|^2),
// with n_f the four face normals scaled by twice the face area (the columns of cof(D) and
// minus their sum); |grad N_a| = 1 / (altitude from node a). With lumped mass, every
// eigenfrequency of the element satisfies omega^2 <= 4 c_d^2 / h_e^2, so dt = h_e / c_d is a
// rigorous bound on the element's (and hence the mesh's) central-difference limit 2 / omega_max.
inline double characteristic_length(const Mat3& D) {
  const Vec3 n0 = D.col(1).cross(D.col(2));
  const Vec3 n1 = D.col(2).cross(D.col(0));
  const Vec3 n2 = D.col(0).cross(D.col(1));
  const double sum_n2 =
      n0.squaredNorm() + n1.squaredNorm() + n2.squaredNorm() + (n0 + n1 + n2).squaredNorm();
  return D.col(0).dot(n0) / std::sqrt(sum_n2);
}

}  // namespace ccm
