#include "rig_models/sim/contact_probe.hpp"

#include <stdexcept>

namespace ccm::rig {

ContactProbe::ContactProbe(ContactModel& inner, std::vector<int> sensor_nodes, const Vec3& axis)
    : ContactModel(inner.name()),
      inner_(inner),
      nodes_(std::move(sensor_nodes)),
      v_before_(nodes_.size()) {
  if (!(axis.norm() > 0.0)) throw std::invalid_argument("contact probe: zero axis");
  axis_ = axis.normalized();
}

void ContactProbe::correct(State& s, double dt) {
  for (size_t j = 0; j < nodes_.size(); ++j) v_before_[j] = s.v[static_cast<size_t>(nodes_[j])];
  inner_.correct(s, dt);
  for (size_t j = 0; j < nodes_.size(); ++j) {
    const auto i = static_cast<size_t>(nodes_[j]);
    impulse_ += s.m_lumped[i] * (s.v[i] - v_before_[j]).dot(axis_);  // F_c dt   (3.3.3)
  }
}

}  // namespace ccm::rig
