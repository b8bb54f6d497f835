#include "engine/bc/pin_joint.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>

#include "engine/core/parameter_ranges.hpp"
#include "engine/core/unit_direction.hpp"

namespace ccm {

PinJoint::PinJoint(PinJointSpec spec, const std::vector<Vec3>& X) : spec_(std::move(spec)) {
  if (spec_.nodes.empty()) throw std::invalid_argument("pin joint: no node");
  e_ = unit_direction(spec_.axis_direction, "pin joint: the axis direction");
  if (!(spec_.mu_s >= 0.0) || !(spec_.mu_k >= 0.0))
    throw std::invalid_argument("pin joint: friction coefficients must be >= 0");
  for (const double v : {spec_.stiffness, spec_.damping})
    if (!kClampRange.contains(v))
      throw std::invalid_argument("pin joint: the clamp's stiffness and damping " +
                                  kClampRange.problem(v));
  double largest = 0.0;
  for (int n : spec_.nodes) {
    const Vec3 d = X.at(static_cast<size_t>(n)) - spec_.axis_point;
    const double axial = d.dot(e_);
    const Vec3 lever = d - axial * e_;
    ring_.push_back({n, lever, axial, lever.norm()});
    largest = std::max(largest, lever.norm());
  }
  if (!(largest > 0.0)) throw std::invalid_argument("pin joint: every node lies on the axis");
}

Vec3 PinJoint::lever(const RingNode& r) const { return Eigen::AngleAxisd(phi_, e_) * r.lever0; }

void PinJoint::initialise(State& s) {
  J_ring_ = 0.0;
  double L = 0.0;
  for (RingNode& r : ring_) {
    r.mass = s.m_lumped[static_cast<size_t>(r.node)];
    J_ring_ += r.mass * r.radius * r.radius;
    L += r.mass * e_.cross(r.lever0).dot(s.v[static_cast<size_t>(r.node)]);
  }
  omega_ = L / J_ring_;  // the ring starts with the rigid rotation closest to its velocities
  for (RingNode& r : ring_) {
    const auto i = static_cast<size_t>(r.node);
    s.v[i] = omega_ * e_.cross(r.lever0);
    r.a_raw = s.a[i];
    r.correction = Vec3::Zero();
    r.x = s.x[i];
    r.v = s.v[i];
    s.a[i] = Vec3::Zero();
  }
}

void PinJoint::apply(State& s, double dt) {
  double L = 0.0, C = 0.0;
  for (const RingNode& r : ring_) {
    if (!(r.radius > 0.0)) continue;
    const auto i = static_cast<size_t>(r.node);
    // The trial end-of-step velocity of the rigid-ring form: the ring's velocity plus half
    // kicks of the last and this step's evaluated accelerations (PJ.2).
    const Vec3 v_end = s.v[i] + 0.5 * dt * (r.a_raw + s.a[i]);
    const Vec3 n = lever(r) / r.radius;
    L += r.mass * r.radius * e_.cross(n).dot(v_end);  // (3.3) as angular momentum
    C += r.mass * r.radius * std::abs(n.dot(v_end));  // (3.2) as angular impulse capacity
  }
  L -= dt * spec_.stiffness * phi_;  // (PJ.1) the clamp's spring at phi_n
  // (3.4): stick below mu_s, else slip with mu_k; kinetic friction never reverses the rotation.
  sticking_ = std::abs(L) <= spec_.mu_s * C;
  double L_new = 0.0;
  if (!sticking_) {
    L_new = L - std::copysign(spec_.mu_k * C, L);
    if (L_new * L <= 0.0) L_new = 0.0;
  }
  omega_ = L_new / (J_ring_ + dt * spec_.damping + dt * dt * spec_.stiffness);  // (PJ.1)
  phi_ += dt * omega_;
  place(s);
}

// (3.5, 3.6): every ring node on its circle at phi, moving with the ring's rate, no acceleration
// left in the state (PJ.3); what that does to the held nodes is booked (PJ.4).
void PinJoint::place(State& s) {
  const Eigen::AngleAxisd rotation(phi_, e_);
  for (RingNode& r : ring_) {
    const auto i = static_cast<size_t>(r.node);
    const Vec3 lever_now = rotation * r.lever0;
    const Vec3 x_new = spec_.axis_point + r.axial * e_ + lever_now;
    const Vec3 v_new = omega_ * e_.cross(lever_now);
    const Vec3 a_raw = s.a[i];
    const Vec3 correction = x_new - s.x[i];
    const Vec3 predicted_move = (x_new - r.x) - (correction - r.correction);  // x*_n+1 - x*_n
    work_ += 0.5 * r.mass * (v_new.squaredNorm() - r.v.squaredNorm()) -       // (PJ.4)
             0.5 * r.mass * (r.a_raw + a_raw).dot(predicted_move);
    r.a_raw = a_raw;
    r.correction = correction;
    r.x = x_new;
    r.v = v_new;
    s.x[i] = x_new;
    s.a[i] = Vec3::Zero();  // (PJ.3)
    s.v[i] = v_new;
  }
}

}  // namespace ccm
