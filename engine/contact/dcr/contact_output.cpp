#include "engine/contact/dcr/contact_output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace ccm::dcr {

ContactOutput::ContactOutput(const ModelMesh& mesh, const std::vector<int>& bodies,
                             ContactOutputRequest request) {
  if (request.force_axis) {
    if (!(request.force_axis->norm() > 0.0))
      throw std::invalid_argument("dcr: force_axis must not be zero");
    axis_ = request.force_axis->normalized();
    for (size_t i = 0; i < bodies.size(); ++i)
      for (size_t j = i + 1; j < bodies.size(); ++j)
        pairs_.push_back(
            {bodies[i], bodies[j],
             fmt::format("contact.{}.{}", mesh.bodies[static_cast<size_t>(bodies[i])].name,
                         mesh.bodies[static_cast<size_t>(bodies[j])].name)});
  }
  for (const std::string& name : request.sensors) {
    const auto it = mesh.surfaces.find(name);
    if (it == mesh.surfaces.end())
      throw std::invalid_argument(fmt::format("dcr: no sensor surface named '{}'", name));
    Sensor s{name, nodes_of(it->second.triangles), {}, 0.0, Vec3::Zero()};
    for (const Triangle& t : it->second.triangles) {
      const auto& X = mesh.X;
      s.area += 0.5 * (X[t[1]] - X[t[0]]).cross(X[t[2]] - X[t[0]]).norm();
    }
    if (!(s.area > 0.0))
      throw std::invalid_argument(fmt::format("dcr: sensor surface '{}' has no area", name));
    sensors_.push_back(std::move(s));
  }
}

ContactOutput::Pair* ContactOutput::pair_of(int a, int b) {
  for (Pair& p : pairs_)
    if (p.a == std::min(a, b) && p.b == std::max(a, b)) return &p;
  return nullptr;
}

void ContactOutput::begin(const State& s) {
  for (Pair& p : pairs_) p.impulse_on_b.setZero();
  for (Sensor& sensor : sensors_) {
    sensor.v_before.resize(sensor.nodes.size());
    for (size_t k = 0; k < sensor.nodes.size(); ++k)
      sensor.v_before[k] = s.v[static_cast<size_t>(sensor.nodes[k])];
  }
}

void ContactOutput::add_impulses(const std::vector<ContactRow>& rows,
                                 const std::vector<PairImpulse>& restitution,
                                 const std::vector<int>& node_body) {
  if (pairs_.empty()) return;
  for (const ContactRow& r : rows) {
    const int first = node_body[static_cast<size_t>(r.nodes[0])];
    const int last = node_body[static_cast<size_t>(r.nodes[3])];
    if (first == last) continue;  // self-contact: no force between two bodies
    Pair* p = pair_of(first, last);
    if (!p) continue;
    const Vec3 tangential = r.lambda_t1 * r.t1 + r.lambda_t2 * r.t2;
    for (int j = 0; j < 4; ++j)
      if (node_body[static_cast<size_t>(r.nodes[j])] == p->b)
        p->impulse_on_b += r.lambda_n * r.grad[j] + r.beta[j] * tangential;
  }
  for (const PairImpulse& c : restitution)
    if (Pair* p = pair_of(c.body_a, c.body_b)) p->impulse_on_b += c.impulse_on_b;
}

void ContactOutput::finish(const State& s, double dt) {
  for (Pair& p : pairs_) p.interval_impulse += p.impulse_on_b;
  for (Sensor& sensor : sensors_)  // sum m dv over the sensor's nodes (3.3.3)
    for (size_t k = 0; k < sensor.nodes.size(); ++k) {
      const auto i = static_cast<size_t>(sensor.nodes[k]);
      sensor.interval_momentum += s.m_lumped[i] * (s.v[i] - sensor.v_before[k]);
    }
  interval_ += dt;
}

std::vector<std::string> ContactOutput::columns() const {
  std::vector<std::string> c;
  for (const Pair& p : pairs_) {
    c.push_back(p.prefix + ".force");
    c.push_back(p.prefix + ".force_axis");
  }
  for (const Sensor& s : sensors_) c.push_back(fmt::format("contact.{}.pressure", s.name));
  return c;
}

void ContactOutput::append(std::vector<double>& row) const {
  // The mean force of the interval: its impulse over its length (0 for the empty interval).
  const double rate = interval_ > 0.0 ? 1.0 / interval_ : 0.0;
  for (const Pair& p : pairs_) {
    const Vec3 force = rate * p.interval_impulse;
    row.push_back(force.norm());
    row.push_back(force.dot(*axis_));
    p.interval_impulse.setZero();
  }
  for (const Sensor& s : sensors_) {
    const Vec3 f = rate * s.interval_momentum;
    row.push_back((axis_ ? std::abs(f.dot(*axis_)) : f.norm()) / s.area);  // eq. 3.8
    s.interval_momentum.setZero();
  }
  interval_ = 0.0;
}

}  // namespace ccm::dcr
