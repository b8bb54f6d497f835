// The motion of one rigid body: its centre of mass c, its orientation q (principal frame to
// world), its linear momentum P and its angular momentum L about c in world axes.
//
// A step of length h is a kick-drift-kick splitting, the same leapfrog as the nodes' central
// difference (docs/rigid-bodies.md, "Time integration"):
//   kick   P += h/2 F,  L += h/2 tau                                     (RB.4)
//   drift  c += h P / m;  the free rotation over h by the implicit midpoint rule on the
//          body-frame angular momentum  Pi' = Pi x I^-1 Pi:
//            Pi_1 = cay(h w)^T Pi_0,  w = I^-1 (Pi_0 + Pi_1) / 2,  q_1 = q_0 cay(h w)   (RB.5)
//          where cay is the Cayley map, the rotation with quaternion (1, h w / 2) / norm
//   kick   P += h/2 F,  L += h/2 tau     (with F, tau at the new pose)
// The drift keeps L in world axes exactly (q_1 Pi_1 = q_0 Pi_0) and the kinetic energy
// Pi^T I^-1 Pi / 2 exactly (the midpoint rule keeps quadratic invariants), so a torque-free body
// keeps both to round-off however long it tumbles. Pi_1 is found by fixed-point iteration to
// round-off: a few iterations for h |w| << 1, about 60 flops each.
#pragma once

#include <Eigen/Geometry>

#include "engine/body/mass_properties.hpp"
#include "engine/core/types.hpp"

namespace ccm {

using Quat = Eigen::Quaterniond;

// The Cayley map of the rotation vector v: the rotation with quaternion (1, v/2) / |(1, v/2)|,
// by the angle 2 atan(|v| / 2) = |v| (1 - |v|^2 / 12 + ...) about v.
Quat cayley_rotation(const Vec3& v);

class RigidBody {
 public:
  // From mass properties in the reference configuration: c = p.center, the principal frame from
  // the eigenvectors of p.inertia. Throws std::invalid_argument when the mass or a principal
  // moment is not positive.
  explicit RigidBody(const MassProperties& p);

  double mass() const { return mass_; }
  const Vec3& principal_moments() const { return moments_; }
  Mat3 inertia_world() const;                     // R diag(moments) R^T at the current orientation
  const Quat& orientation() const { return q_; }  // principal frame to world, now

  const Vec3& center() const { return c_; }
  const Vec3& reference_center() const { return c0_; }
  // The rotation since the reference configuration (world to world), as a unit quaternion.
  Quat rotation() const { return (q_ * q0_.conjugate()).normalized(); }
  Vec3 velocity() const { return P_ / mass_; }
  Vec3 angular_velocity() const;  // world axes
  const Vec3& momentum() const { return P_; }
  const Vec3& angular_momentum() const { return L_; }  // about c, world axes
  double kinetic_energy() const;

  void set_velocity(const Vec3& v) { P_ = mass_ * v; }
  void set_angular_velocity(const Vec3& w);  // world axes
  // Places the body with its rotation since the reference and its centre (prescribed motion).
  void set_pose(const Vec3& center, const Quat& rotation);

  // The current position of a material point at X in the reference configuration, and the
  // velocity of the material point now at x.
  Vec3 position_of(const Vec3& X) const { return c_ + rotation() * (X - c0_); }
  Vec3 velocity_at(const Vec3& x) const { return velocity() + angular_velocity().cross(x - c_); }

  // RB.4: momentum and angular momentum (about c) change by h F and h tau.
  void kick(const Vec3& force, const Vec3& torque, double h);
  // RB.5. Returns false when the midpoint iteration did not converge (h |w| too large).
  bool drift(double h);

 private:
  double mass_ = 0.0;
  Vec3 moments_ = Vec3::Ones();  // principal moments of inertia
  Vec3 c0_ = Vec3::Zero();
  Quat q0_ = Quat::Identity();  // principal frame at the reference
  Vec3 c_ = Vec3::Zero();
  Quat q_ = Quat::Identity();  // principal frame to world
  Vec3 P_ = Vec3::Zero();
  Vec3 L_ = Vec3::Zero();
};

}  // namespace ccm
