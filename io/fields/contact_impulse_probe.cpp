#include "io/fields/contact_impulse_probe.hpp"

#include <algorithm>

namespace ccm::fields {

ContactImpulseProbe::ContactImpulseProbe(ContactModel& inner, std::vector<int> nodes)
    : ContactModel(inner.name(), inner.phases()),
      inner_(inner),
      nodes_(std::move(nodes)),
      impulse_(nodes_.size(), Vec3::Zero()),
      before_(nodes_.size()),
      last_force_(nodes_.size(), Vec3::Zero()) {}

void ContactImpulseProbe::begin_step(const State& s, double dt) {
  dt_ = dt;
  inner_.begin_step(s, dt);
}

void ContactImpulseProbe::add_forces(State& s) {
  for (size_t k = 0; k < nodes_.size(); ++k) before_[k] = s.f[static_cast<size_t>(nodes_[k])];
  inner_.add_forces(s);
  for (size_t k = 0; k < nodes_.size(); ++k) {
    const Vec3 force = s.f[static_cast<size_t>(nodes_[k])] - before_[k];
    impulse_[k] += 0.5 * dt_ * (last_force_[k] + force);  // trapezoid of eq. 2.31
    last_force_[k] = force;
  }
}

void ContactImpulseProbe::correct(State& s, double dt) {
  for (size_t k = 0; k < nodes_.size(); ++k) before_[k] = s.v[static_cast<size_t>(nodes_[k])];
  inner_.correct(s, dt);
  for (size_t k = 0; k < nodes_.size(); ++k) {
    const auto i = static_cast<size_t>(nodes_[k]);
    impulse_[k] += s.m_lumped[i] * (s.v[i] - before_[k]);
  }
}

}  // namespace ccm::fields
