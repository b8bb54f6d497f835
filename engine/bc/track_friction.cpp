#include "engine/bc/track_friction.hpp"

#include <cmath>
#include <stdexcept>

#include "engine/core/parameter_ranges.hpp"
#include "engine/core/unit_direction.hpp"

namespace ccm {

TrackFriction::TrackFriction(TrackFrictionSpec spec) : spec_(std::move(spec)) {
  if (spec_.nodes.empty()) throw std::invalid_argument("track friction: no node");
  d_ = unit_direction(spec_.direction, "track friction: the direction");
  for (const double v : {spec_.mu_s, spec_.mu_k})
    if (!kFrictionRange.contains(v))
      throw std::invalid_argument("track friction: a coefficient " + kFrictionRange.problem(v));
  if (spec_.mu_k > spec_.mu_s)
    throw std::invalid_argument("track friction: mu_k must be at most mu_s");
  for (const double v : {spec_.normal_force, spec_.damping})
    if (!kDampingRange.contains(v))
      throw std::invalid_argument("track friction: the normal force and the damping " +
                                  kDampingRange.problem(v));
}

// The group's mass-weighted mean displacement along the track.
double TrackFriction::displacement(const State& s) const {
  double u = 0.0;
  for (int n : spec_.nodes) {
    const auto i = static_cast<size_t>(n);
    u += s.m_lumped[i] * (s.x[i] - s.X[i]).dot(d_);
  }
  return u / M_;
}

// Along d: the group's momentum and the force on it (sum m a . d).
std::pair<double, double> TrackFriction::momentum_and_force(const State& s) const {
  double P = 0.0, F = 0.0;
  for (int n : spec_.nodes) {
    const auto i = static_cast<size_t>(n);
    P += s.m_lumped[i] * s.v[i].dot(d_);
    F += s.m_lumped[i] * s.a[i].dot(d_);
  }
  return {P, F};
}

// The friction joins the group's accelerations, so that both half kicks of the leapfrog carry it.
void TrackFriction::add_to_accelerations(State& s, double force) {
  force_ = force;
  const Vec3 da = (force / M_) * d_;
  for (int n : spec_.nodes) s.a[static_cast<size_t>(n)] += da;
}

// At t = 0 there is no step yet: the force form of TF.1-TF.3 on the initial state.
void TrackFriction::initialise(State& s) {
  M_ = 0.0;
  for (int n : spec_.nodes) M_ += s.m_lumped.at(static_cast<size_t>(n));
  if (!(M_ > 0.0)) throw std::invalid_argument("track friction: the group has no mass");
  u_ = displacement(s);
  if (s.t < spec_.active_from) return;
  const auto [P, F] = momentum_and_force(s);
  const double v = P / M_;
  sticking_ = v == 0.0 && std::abs(F) <= spec_.mu_s * spec_.normal_force;
  if (sticking_) return add_to_accelerations(s, -F);
  const double direction = v != 0.0 ? v : F;
  add_to_accelerations(
      s, -std::copysign(spec_.mu_k * spec_.normal_force, direction) - spec_.damping * v);
}

// On entry s.v holds v_{n+1/2} and s.a the forces' a_{n+1}; the momentum the next half step
// would reach without friction, P = sum m (v + dt a) . d, goes through TF.1-TF.3, and the
// force that gives the result joins a_{n+1}.
void TrackFriction::apply(State& s, double dt) {
  const double u = displacement(s);
  double force = 0.0;
  sticking_ = false;
  if (s.t >= spec_.active_from) {
    const auto [P_half, F] = momentum_and_force(s);
    const double P = P_half + dt * F;
    const double viscous = P / (1.0 + dt * spec_.damping / M_);  // (TF.1)
    const double hold = spec_.normal_force * dt;
    sticking_ = std::abs(viscous) <= spec_.mu_s * hold;  // (TF.2)
    double P_new = 0.0;
    if (!sticking_) {
      P_new = viscous - std::copysign(spec_.mu_k * hold, viscous);  // (TF.3)
      if (P_new * viscous <= 0.0) P_new = 0.0;
    }
    force = (P_new - P) / dt;
    add_to_accelerations(s, force);
  } else {
    force_ = 0.0;
  }
  // Its work on the group, trapezoidal in time as the loads' (the group moves as its mean).
  work_ += 0.5 * (force_before_ + force) * (u - u_);
  force_before_ = force;
  u_ = u;
}

}  // namespace ccm
