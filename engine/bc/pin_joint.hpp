// A pin joint with Coulomb friction: the free artifact's rotational boundary condition (thesis
// 3.3.2, eqs. 3.2-3.6), in rigid-ring form. The nodes the pin holds (the surface of the bore the
// pin passes through) turn as one rigid ring about the pin axis (centre c, unit direction e):
// their radius does not change (3.5), they do not move along the axis, and one angle phi says
// where they are. The pin resists the rotation with Coulomb friction driven by its reaction.
//
// Each step, on the trial end-of-step velocities of the ring nodes (lumped mass m_j, radius r_j,
// radial unit n_j and tangential unit t_j = e x n_j at phi_n), the ring's velocity at the last
// step plus half kicks of the accelerations evaluated then and now,
//   v_j = v_j,n + dt/2 (a_j,n + a_j,n+1)                                             (PJ.2)
//   L = sum_j m_j r_j (t_j . v_j)    angular momentum about the axis, the ring's "ideal"
//                                     tangential motion (v_t,ideal of 3.3)
//   C = sum_j m_j r_j |n_j . v_j|    angular impulse the friction can hold: the radial momentum
//                                     the pin takes out this step (its reaction, v_n of 3.2)
//                                     times its arm
//   stick if |L| <= mu_s C:  omega = 0                                               (3.4)
//   slip  otherwise:         omega = (L - mu_k C sign L) / J_ring, never reversed      (3.4)
//   phi_{n+1} = phi_n + dt omega,  x_j = c + R(phi_{n+1}) (X_j - c),
//   v_j = omega e x (x_j - c)                                                    (3.5, 3.6)
// with J_ring = sum_j m_j r_j^2.
//
// What the ring leaves in the state is its own motion, as fixed nodes do: x_j on the circle,
// v_j = v_j,n+1 and no acceleration,
//   a_j <- 0,   v*_j <- v_j,n+1                                                       (PJ.3)
// so that the next predictor moves the held nodes along the ring at its rate, not off it by
// dt^2/2 of their evaluated acceleration, which carries the pin's reaction (tens of newtons on
// grams where a clamp holds a blow: the elements were evaluated, and the energy measured, at
// positions the ring never takes, 0.7 % of the rig's RX cases' energy read wrongly while the
// clamp was loaded). The evaluated accelerations are kept for PJ.2. What the constraint does to
// the held nodes is booked as its work: their kinetic energy's change less the work of the
// evaluated forces over the predicted positions x* (at which the elements' energy is measured),
//   W += m_j (|v_j,n+1|^2 - |v_j,n|^2) / 2 - m_j (a_j,n + a_j,n+1) / 2 . (x*_j,n+1 - x*_j,n)
//                                                                                  (PJ.4)
// (trapezoidal, as the loads' work). The spring's stored k phi^2 / 2, the friction's and the
// damper's losses are all in it.
//
// Per node, 3.4 is |dv_t| <= mu |v_n|: multiplied by m_j r_j and summed over the ring it is
// the limit on C above, so the friction torque is mu times the pin's reaction times the bore
// radius, which is Coulomb's law for a pin. Departures from the thesis, all deliberate: the
// ring turns rigidly (per-node angles would let the bore shear); radial motion either way
// loads the pin (3.2 counts outward motion only, but 3.5 holds the radius both ways); and phi
// advances by dt omega (3.6 as printed, theta = v_t / r, is not dimensionally an angle;
// docs/equations.md "Pin joint with Coulomb friction"). With mu_s = mu_k = 0 the reaction exerts no
// torque about the axis: the angular momentum of the body about the axis is kept.
//
// A clamp (a pin held by a tightened screw that still lets it deflect, thesis 3.4.1) adds a
// torsional spring k and damper c about the axis on the ring, torque -k phi - c omega. Both enter
// the ring's update implicitly, so the stiff spring on the light ring never limits the step:
//   L' = L - dt k phi_n                                  the spring's impulse at phi_n
//   stick/slip (3.4) on L' as above, giving L''
//   omega = L'' / (J_ring + dt c + dt^2 k)               k phi_{n+1} = k (phi_n + dt omega)  (PJ.1)
// The spring's and the damper's torques act on the ring as its other reactions do, so their
// work is booked with the constraint's; spring_energy() = k phi^2 / 2 is the part of it stored.
// With k = c = 0 the update is the frictional pin's.
#pragma once

#include <vector>

#include "engine/bc/kinematic_constraint.hpp"

namespace ccm {

struct PinJointSpec {
  std::vector<int> nodes;          // nodes held by the pin (sorted unique not required)
  Vec3 axis_point = Vec3::Zero();  // a point on the pin axis [m]
  Vec3 axis_direction = Vec3::UnitX();
  double mu_s = 0.0;       // static coefficient
  double mu_k = 0.0;       // kinetic coefficient
  double stiffness = 0.0;  // N m/rad, torsional spring of a clamp about the axis (PJ.1)
  double damping = 0.0;    // N m s/rad, its damper
};

class PinJoint : public KinematicConstraint {
 public:
  // X: the reference positions of the model. Throws std::invalid_argument when there is no
  // node, the axis direction is zero or not finite, a coefficient is negative, or every node
  // lies on the axis (no ring to turn), or the clamp's stiffness or damping is negative or not
  // finite.
  PinJoint(PinJointSpec spec, const std::vector<Vec3>& X);

  std::string_view name() const override { return "pin_joint"; }
  const std::vector<int>& nodes() const override { return spec_.nodes; }
  void initialise(State& s) override;
  void apply(State& s, double dt) override;
  double work() const override { return work_; }

  double angle() const { return phi_; }   // rotation about e since t = 0 [rad]
  double rate() const { return omega_; }  // [rad/s]
  bool sticking() const { return sticking_; }
  double spring_energy() const { return 0.5 * spec_.stiffness * phi_ * phi_; }  // J
  double ring_inertia() const { return J_ring_; }  // kg m^2 about the axis
  const PinJointSpec& spec() const { return spec_; }

 private:
  struct RingNode {
    int node;
    Vec3 lever0;   // (X - c) without its axial part, at phi = 0
    double axial;  // (X - c) . e
    double radius;
    double mass = 0.0;
    // The last step's (place): the evaluated acceleration, the step from the predicted
    // position to the ring's (x - x*), and the position and velocity the ring gave the node.
    Vec3 a_raw = Vec3::Zero(), correction = Vec3::Zero(), x = Vec3::Zero(), v = Vec3::Zero();
  };
  Vec3 lever(const RingNode& r) const;  // at phi_
  void place(State& s);                 // positions and velocities of the ring at phi_, omega_

  PinJointSpec spec_;
  Vec3 e_;
  std::vector<RingNode> ring_;
  double J_ring_ = 0.0;
  double phi_ = 0.0;
  double omega_ = 0.0;
  bool sticking_ = false;
  double work_ = 0.0;
};

}  // namespace ccm
