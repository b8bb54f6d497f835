// Coulomb (static and kinetic) and viscous friction on a group of nodes that runs along a track:
// a carriage on its rails (the rig's impactor, thesis 3.2.1 and 3.5: the track's friction the
// open-loop drive does not carry once contact starts). The normal force N is given (the
// carriage's weight on a level track). On the group's trial end-of-step momentum along the
// track d (unit) at the next half step without friction, P = sum_j m_j (v_{n+1/2} + dt a_{n+1}) .
// d, with M = sum_j m_j:
//
//   P' = P / (1 + dt c / M)                      viscous, implicit (never reverses)    (TF.1)
//   stick if |P'| <= mu_s N dt:   P'' = 0                                               (TF.2)
//   slip  otherwise:              P'' = P' - mu_k N dt sign P', set to 0 if reversed      (TF.3)
//
// and the friction force (P'' - P) / dt joins the accelerations of the group's nodes (the same
// acceleration for all), so both half kicks of the leapfrog carry it. A group at rest therefore
// breaks away exactly when the force on it along the track exceeds mu_s N, and a sticking group
// stays at rest to round-off: no regularisation, no chatter. Its work on the group's mean
// displacement is booked (trapezoidal in time, as the loads').
// The friction acts from `active_from` on (the open-loop drive's measured motion carries it
// before the contact).
#pragma once

#include <utility>
#include <vector>

#include "engine/bc/kinematic_constraint.hpp"

namespace ccm {

struct TrackFrictionSpec {
  std::vector<int> nodes;          // the group (a body's nodes, or its running faces')
  Vec3 direction = Vec3::UnitY();  // the track
  double normal_force = 0.0;       // N >= 0 [N]
  double mu_s = 0.0, mu_k = 0.0;   // 0 <= mu_k <= mu_s
  double damping = 0.0;            // c >= 0 [N s/m]
  double active_from = 0.0;        // s, simulation time
};

class TrackFriction : public KinematicConstraint {
 public:
  // Throws std::invalid_argument when there is no node, the direction is zero or not finite,
  // a coefficient, the normal force or the damping is negative or not finite, or mu_k > mu_s.
  explicit TrackFriction(TrackFrictionSpec spec);

  std::string_view name() const override { return "track_friction"; }
  const std::vector<int>& nodes() const override { return spec_.nodes; }
  void initialise(State& s) override;
  void apply(State& s, double dt) override;
  double work() const override { return work_; }

  bool sticking() const { return sticking_; }
  double force() const { return force_; }  // N along d at the last step (negative: resisting)

 private:
  double displacement(const State& s) const;
  std::pair<double, double> momentum_and_force(const State& s) const;
  void add_to_accelerations(State& s, double force);

  TrackFrictionSpec spec_;
  Vec3 d_;
  double M_ = 0.0;
  bool sticking_ = false;
  double force_ = 0.0, force_before_ = 0.0;
  double u_ = 0.0;  // the group's mean displacement at the last step
  double work_ = 0.0;
};

}  // namespace ccm
