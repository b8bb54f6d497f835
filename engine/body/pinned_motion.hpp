// A rigid body turning about a fixed pin (motion = "pinned", docs/rigid-bodies.md "Pinned"):
// one degree of freedom, the angle phi about the unit axis e through the point p, with the pin's
// Coulomb friction (the rig's pin joint, engine/bc/pin_joint.hpp, for a rigid body).
//
// With d = c - p the lever of the centre of mass, the moment of inertia about the axis
//   J = e^T I_c e + m |d_perp|^2,  d_perp = d - (e . d) e          (parallel axes; RB.7)
// is constant (a rotation about e keeps both terms). The step is the same kick-drift-kick as a
// free body's (RB.4-RB.5), on the axial angular momentum J omega:
//   kick   J omega += h tau_e,  tau_e = e . (tau_c + d x F)          (RB.8)
//          then the pin's friction takes at most mu h |R| r_pin of it, never reversing omega:
//          R = m a_c - F the pin's reaction, a_c = (tau_e / J) e x d - omega^2 d_perp the
//          frictionless acceleration of the centre; sticking (omega = 0 before the kick) holds
//          while |h tau_e| <= mu_s h |R| r_pin                                  (RB.9)
//   drift  phi += h omega; c = p + R_e(phi) (c_0 - p), rotation R_e(phi),
//          V = omega e x d, angular velocity omega e
// The drift is exact (a rotation about a fixed axis at constant rate), so the scheme is the
// Stormer-Verlet of the pendulum equation J phi'' = tau_e(phi): symplectic, period error
// O((h omega)^2). The kinetic energy J omega^2 / 2 lost to the friction is booked as its work.
#pragma once

#include "engine/body/rigid_body.hpp"
#include "engine/core/types.hpp"

namespace ccm {

struct RigidPin {
  Vec3 point = Vec3::Zero();  // p, a point on the axis [m]
  Vec3 axis = Vec3::UnitZ();  // e, non-zero (normalised by PinnedMotion)
  double mu_s = 0.0;          // static coefficient of the pin's friction
  double mu_k = 0.0;          // kinetic coefficient
  double radius = 0.0;        // r_pin, the arm of the friction [m]; 0: frictionless
};

class PinnedMotion {
 public:
  // body: in its reference pose. rate: the initial angular velocity about e [rad/s]. Throws
  // std::invalid_argument for a zero or non-finite axis or a negative coefficient or radius.
  PinnedMotion(const RigidBody& body, const RigidPin& pin, double rate);

  double axial_inertia() const { return J_; }  // J of RB.7 [kg m^2]
  double angle() const { return phi_; }        // [rad] since the reference
  double rate() const { return omega_; }       // [rad/s] about e
  const Vec3& axis() const { return e_; }
  const Vec3& pivot() const { return pin_.point; }  // p
  double friction_work() const { return friction_work_; }  // [J], <= 0

  // RB.8-RB.9 over h with the resultant force F and the moment about c of the body's loads.
  void kick(const RigidBody& body, const Vec3& force, const Vec3& torque_about_c, double h);
  // An impulse J and its moment about the origin M (a contact's, on the held body): the axial
  // angular impulse e . (M - p x J) changes J omega; the pin takes the rest.
  void take_impulse(const Vec3& impulse, const Vec3& moment);
  // phi += h omega, and the body placed and moving accordingly.
  void drift(RigidBody& body, double h);
  // The body placed and moving at the current phi and omega.
  void place(RigidBody& body) const;

 private:
  RigidPin pin_;
  Vec3 e_;
  Vec3 lever0_;  // c_0 - p
  double J_ = 0.0;
  double phi_ = 0.0;
  double omega_ = 0.0;
  double friction_work_ = 0.0;
};

}  // namespace ccm
