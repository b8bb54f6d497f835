#include "engine/body/rigid_bodies.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace ccm {

std::string_view to_string(RigidMotion m) {
  switch (m) {
    case RigidMotion::free:
      return "free";
    case RigidMotion::fixed:
      return "fixed";
    case RigidMotion::prescribed:
      return "prescribed";
    case RigidMotion::pinned:
      return "pinned";
  }
  return "?";
}

namespace {

Vec3 at(const std::array<TimeTable, 3>& table, double t) {
  return Vec3(table[0](t), table[1](t), table[2](t));
}

}  // namespace

RigidBodies::RigidBodies(const ModelMesh& mesh, const std::vector<RigidBodyModel>& models)
    : mesh_(mesh) {
  for (const RigidBodyModel& m : models) {
    models_.push_back(&m);
    bodies_.emplace_back(m.mass);
    RigidBody& b = bodies_.back();
    if (m.motion == RigidMotion::free) {
      b.set_velocity(m.velocity);
      b.set_angular_velocity(m.angular_velocity);
    } else if (m.motion == RigidMotion::prescribed) {
      b.set_velocity(at(m.prescribed_velocity, 0.0));
      b.set_angular_velocity(at(m.prescribed_angular_velocity, 0.0));
    }
    pins_.emplace_back();
    if (m.motion == RigidMotion::pinned) {
      pins_.back().emplace(b, m.pin, m.pin.axis.normalized().dot(m.angular_velocity));
      pins_.back()->place(b);
    }
  }
  for (const RigidBodyModel& m : models) split_nodes(mesh.bodies[static_cast<size_t>(m.body)]);
  force_.assign(bodies_.size(), Vec3::Zero());
  torque_.assign(bodies_.size(), Vec3::Zero());
  impulse_.assign(mesh.bodies.size(), HeldImpulse{});
  contact_impulse_.assign(bodies_.size(), Vec3::Zero());
  contact_angular_impulse_.assign(bodies_.size(), Vec3::Zero());
}

// A body's nodes on its boundary triangles (what contact and loads read every step) and the rest.
void RigidBodies::split_nodes(const Body& body) {
  std::vector<char> on_surface(static_cast<size_t>(body.n_nodes), 0);
  for (const Triangle& t : body.boundary)
    for (int n : t) on_surface[static_cast<size_t>(n - body.first_node)] = 1;
  surface_nodes_.emplace_back();
  interior_nodes_.emplace_back();
  for (int n = body.first_node; n < body.first_node + body.n_nodes; ++n)
    (on_surface[static_cast<size_t>(n - body.first_node)] ? surface_nodes_ : interior_nodes_)
        .back()
        .push_back(n);
}

void RigidBodies::publish(int k, State& s) const {
  const RigidBody& b = body(k);
  RigidState& r = s.rigid[static_cast<size_t>(k)];
  r.body = model(k).body;
  r.center = b.center();
  r.reference_center = b.reference_center();
  r.rotation = b.rotation();
  r.velocity = b.velocity();
  r.angular_velocity = b.angular_velocity();
  r.kinetic_energy = b.kinetic_energy();
  r.contact_impulse = contact_impulse_[static_cast<size_t>(k)];
  r.contact_angular_impulse = contact_angular_impulse_[static_cast<size_t>(k)];
  if (const PinnedMotion* p = pin(k)) {  // turns about the pin only: e e^T / J about its point
    r.inverse_inertia = p->axis() * p->axis().transpose() / p->axial_inertia();
    r.pivot = p->pivot();
    return;
  }
  if (model(k).motion != RigidMotion::free) return;  // a contact holds the others as anchored
  const Mat3 R = b.orientation().toRotationMatrix();
  r.inverse_mass = 1.0 / b.mass();
  r.inverse_inertia = R * b.principal_moments().cwiseInverse().asDiagonal() * R.transpose();
  r.pivot = b.center();
  r.pivot_velocity = b.velocity();
}

void RigidBodies::place_nodes(int k, State& s, const std::vector<int>& nodes) const {
  const RigidBody& b = bodies_[static_cast<size_t>(k)];
  const Mat3 R = b.rotation().toRotationMatrix();
  const Vec3 c0 = b.reference_center(), c = b.center(), V = b.velocity();
  const Vec3 w = b.angular_velocity();
  for (int n : nodes) {
    const auto i = static_cast<size_t>(n);
    const Vec3 r = R * (s.X[i] - c0);
    s.x[i] = c + r;
    s.v[i] = V + w.cross(r);
  }
}

void RigidBodies::initialise(State& s) const {
  s.rigid.assign(bodies_.size(), RigidState{});
  for (int k = 0; k < size(); ++k) {
    publish(k, s);
    if (model(k).motion != RigidMotion::fixed) {
      place_nodes(k, s, surface_nodes_[static_cast<size_t>(k)]);
      place_nodes(k, s, interior_nodes_[static_cast<size_t>(k)]);
      continue;
    }
    const Body& body = mesh_.bodies[static_cast<size_t>(model(k).body)];  // x = X exactly
    for (int n = body.first_node; n < body.first_node + body.n_nodes; ++n)
      s.v[static_cast<size_t>(n)].setZero();
  }
}

void RigidBodies::gather(State& s, const Vec3& gravity) {
  for (int k = 0; k < size(); ++k) {
    const RigidBody& b = bodies_[static_cast<size_t>(k)];
    const Body& body = mesh_.bodies[static_cast<size_t>(models_[static_cast<size_t>(k)]->body)];
    Vec3 F = b.mass() * gravity, tau = Vec3::Zero();
    for (int n = body.first_node; n < body.first_node + body.n_nodes; ++n) {
      const auto i = static_cast<size_t>(n);
      F += s.f[i];
      tau += (s.x[i] - b.center()).cross(s.f[i]);
      s.a[i].setZero();
    }
    force_[static_cast<size_t>(k)] = F;
    torque_[static_cast<size_t>(k)] = tau;
  }
}

void RigidBodies::predict(State& s, double dt, double t_n) {
  for (int k = 0; k < size(); ++k) {
    RigidBody& b = bodies_[static_cast<size_t>(k)];
    const RigidBodyModel& m = *models_[static_cast<size_t>(k)];
    if (m.motion == RigidMotion::fixed) continue;
    if (m.motion == RigidMotion::pinned) {
      pins_[static_cast<size_t>(k)]->kick(b, force_[static_cast<size_t>(k)],
                                          torque_[static_cast<size_t>(k)], 0.5 * dt);
      pins_[static_cast<size_t>(k)]->drift(b, dt);
    } else if (m.motion == RigidMotion::free) {
      b.kick(force_[static_cast<size_t>(k)], torque_[static_cast<size_t>(k)], 0.5 * dt);
      if (!b.drift(dt) && failure_.empty())
        failure_ = fmt::format(
            "rigid body '{}': its rotation did not converge in a step of {:.3g} s (|omega| dt = "
            "{:.3g})",
            mesh_.bodies[static_cast<size_t>(m.body)].name, dt, b.angular_velocity().norm() * dt);
    } else {
      // Midpoint velocities over the step: exact for histories linear within it.
      const double t_mid = t_n + 0.5 * dt;
      const Vec3 V = at(m.prescribed_velocity, t_mid), w = at(m.prescribed_angular_velocity, t_mid);
      b.set_pose(b.center() + dt * V, cayley_rotation(dt * w) * b.rotation());
      b.set_velocity(V);
      b.set_angular_velocity(w);
    }
    place_nodes(k, s, surface_nodes_[static_cast<size_t>(k)]);
    publish(k, s);
  }
}

void RigidBodies::place_interior(State& s) const {
  for (int k = 0; k < size(); ++k)
    if (model(k).motion != RigidMotion::fixed)
      place_nodes(k, s, interior_nodes_[static_cast<size_t>(k)]);
}

void RigidBodies::take_impulses(const std::vector<HeldImpulse>& per_body) {
  for (size_t b = 0; b < per_body.size() && b < impulse_.size(); ++b) {
    impulse_[b].impulse += per_body[b].impulse;
    impulse_[b].moment += per_body[b].moment;
  }
}

void RigidBodies::finish(State& s, double dt) {
  for (int k = 0; k < size(); ++k) {
    RigidBody& b = bodies_[static_cast<size_t>(k)];
    const RigidBodyModel& m = *models_[static_cast<size_t>(k)];
    const HeldImpulse J = impulse_[static_cast<size_t>(m.body)];
    impulse_[static_cast<size_t>(m.body)] = HeldImpulse{};
    const Vec3 angular = J.moment - b.center().cross(J.impulse);  // about c
    contact_impulse_[static_cast<size_t>(k)] += J.impulse;
    contact_angular_impulse_[static_cast<size_t>(k)] += angular;
    if (m.motion == RigidMotion::free) {
      const double before = b.kinetic_energy();
      b.kick(J.impulse, angular, 1.0);
      contact_work_ += b.kinetic_energy() - before;
      b.kick(force_[static_cast<size_t>(k)], torque_[static_cast<size_t>(k)], 0.5 * dt);
    } else if (m.motion == RigidMotion::pinned) {
      PinnedMotion& pin = *pins_[static_cast<size_t>(k)];
      const double before = b.kinetic_energy();
      pin.take_impulse(J.impulse, J.moment);
      pin.place(b);
      contact_work_ += b.kinetic_energy() - before;
      pin.kick(b, force_[static_cast<size_t>(k)], torque_[static_cast<size_t>(k)], 0.5 * dt);
      pin.place(b);
    } else if (m.motion == RigidMotion::prescribed) {
      b.set_velocity(at(m.prescribed_velocity, s.t));
      b.set_angular_velocity(at(m.prescribed_angular_velocity, s.t));
    }
    if (m.motion != RigidMotion::fixed) place_nodes(k, s, surface_nodes_[static_cast<size_t>(k)]);
    publish(k, s);
  }
}

double RigidBodies::kinetic_energy() const {
  double e = 0.0;
  for (int k = 0; k < size(); ++k)
    if (!model(k).kinematic()) e += body(k).kinetic_energy();
  return e;
}

double RigidBodies::joint_work() const {
  double w = 0.0;
  for (const std::optional<PinnedMotion>& pin : pins_)
    if (pin) w += pin->friction_work();
  return w;
}

double RigidBodies::gravity_work(const Vec3& gravity) const {
  double w = 0.0;
  for (int k = 0; k < size(); ++k)
    if (!model(k).kinematic())
      w += body(k).mass() * gravity.dot(body(k).center() - body(k).reference_center());
  return w;
}

std::vector<int> kinematic_rigid_nodes(const ModelMesh& mesh,
                                       const std::vector<RigidBodyModel>& models) {
  std::vector<int> nodes;
  for (const RigidBodyModel& m : models) {
    if (!m.kinematic()) continue;
    const Body& body = mesh.bodies[static_cast<size_t>(m.body)];
    for (int n = body.first_node; n < body.first_node + body.n_nodes; ++n) nodes.push_back(n);
  }
  std::sort(nodes.begin(), nodes.end());
  return nodes;
}

}  // namespace ccm
