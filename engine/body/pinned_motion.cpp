#include "engine/body/pinned_motion.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>

namespace ccm {

PinnedMotion::PinnedMotion(const RigidBody& body, const RigidPin& pin, double rate)
    : pin_(pin), lever0_(body.reference_center() - pin.point), omega_(rate) {
  const double n = pin.axis.norm();
  if (!std::isfinite(n) || n == 0.0)
    throw std::invalid_argument("pinned rigid body: the pin axis must be a finite non-zero vector");
  if (!(pin.mu_s >= 0.0) || !(pin.mu_k >= 0.0) || !(pin.radius >= 0.0))
    throw std::invalid_argument(
        "pinned rigid body: the pin's friction coefficients and radius must be >= 0");
  e_ = pin.axis / n;
  const Vec3 d_perp = lever0_ - e_.dot(lever0_) * e_;
  J_ = e_.dot(body.inertia_world() * e_) + body.mass() * d_perp.squaredNorm();  // RB.7
}

void PinnedMotion::kick(const RigidBody& body, const Vec3& force, const Vec3& torque_about_c,
                        double h) {
  const Vec3 d = body.center() - pin_.point;
  const double tau = e_.dot(torque_about_c + d.cross(force));  // RB.8
  const double before = omega_;
  omega_ += h * tau / J_;
  if (pin_.radius == 0.0 || (pin_.mu_s == 0.0 && pin_.mu_k == 0.0)) return;
  // RB.9: the reaction of the frictionless motion, and the angular impulse friction can hold.
  const Vec3 d_perp = d - e_.dot(d) * e_;
  const Vec3 a_c = (tau / J_) * e_.cross(d) - before * before * d_perp;
  const double hold = h * (body.mass() * a_c - force).norm() * pin_.radius;
  const double kinetic = 0.5 * J_ * omega_ * omega_;
  if (before == 0.0 && std::abs(J_ * omega_) <= pin_.mu_s * hold)
    omega_ = 0.0;  // sticks
  else if (std::abs(J_ * omega_) <= pin_.mu_k * hold)
    omega_ = 0.0;  // slows to rest, never reversed
  else
    omega_ -= std::copysign(pin_.mu_k * hold / J_, omega_);
  friction_work_ += 0.5 * J_ * omega_ * omega_ - kinetic;
}

void PinnedMotion::take_impulse(const Vec3& impulse, const Vec3& moment) {
  omega_ += e_.dot(moment - pin_.point.cross(impulse)) / J_;
}

void PinnedMotion::drift(RigidBody& body, double h) {
  phi_ += h * omega_;
  place(body);
}

void PinnedMotion::place(RigidBody& body) const {
  const Eigen::AngleAxisd turn(phi_, e_);
  const Vec3 d = turn * lever0_;
  body.set_pose(pin_.point + d, Quat(turn));
  body.set_velocity(omega_ * e_.cross(d));
  body.set_angular_velocity(omega_ * e_);
}

}  // namespace ccm
