#include "engine/contact/dcr/pair_restitution.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ccm::dcr {
namespace {

Vec3 end_velocity(const State& s, double dt, size_t i) { return s.v[i] + 0.5 * dt * s.a[i]; }

// The kinetic energy an impulse J at P gives a rigid body (it takes J at the end of the step, as
// a held impulse): J . v(P) + (|J|^2 / m + (r x J)^T I^-1 (r x J)) / 2, r = P - its pivot.
double rigid_energy_change(const BodyRigidPart& body, const Vec3& J, const Vec3& P) {
  const Vec3 rJ = (P - body.centre).cross(J);
  return J.dot(body.velocity_at(P)) +
         0.5 * (J.squaredNorm() / body.mass + rJ.dot(body.inv_inertia * rJ));
}

}  // namespace

PairRestitution::PairRestitution(const ModelMesh& mesh, double restitution,
                                 std::vector<bool> anchored)
    : e_(restitution), anchored_(std::move(anchored)) {
  for (const Body& b : mesh.bodies) bodies_.push_back({b.first_node, b.n_nodes});
}

namespace {

// A free or pinned rigid body (engine/body/): its own mobility, about its pivot (the centre of
// mass, or a point of the pin, which does not move), from the published state. Null otherwise.
const RigidState* mobile_rigid(int body, const State& s) {
  for (const RigidState& r : s.rigid)
    if (r.body == body && r.mobile()) return &r;
  return nullptr;
}

}  // namespace

// Mass, centre, linear and angular velocity of one body (angular: omega = I^-1 L about the
// centre, I = sum m (|r|^2 1 - r r^T)). A free or pinned rigid body's are its own (a pinned one's
// mass is infinite: 1/m = 0). A fixed or prescribed rigid body's nodes carry no lumped mass: it
// is anchored here, and its motion is read with equal node weights, which recover a rigid
// velocity field exactly.
BodyRigidPart PairRestitution::motion_of(int body, const State& s, double dt) const {
  if (const RigidState* r = mobile_rigid(body, s))
    return {.mass = r->inverse_mass > 0.0 ? 1.0 / r->inverse_mass
                                          : std::numeric_limits<double>::infinity(),
            .centre = r->pivot,
            .velocity = r->pivot_velocity,
            .omega = r->angular_velocity,
            .inv_inertia = r->inverse_inertia};
  const NodeRange& b = bodies_[static_cast<size_t>(body)];
  bool massless = true;
  for (int n = b.first; n < b.first + b.count && massless; ++n)
    massless = s.m_lumped[static_cast<size_t>(n)] == 0.0;
  auto weight = [&](size_t i) { return massless ? 1.0 : s.m_lumped[i]; };
  BodyRigidPart r;
  Vec3 p = Vec3::Zero(), mx = Vec3::Zero();
  for (int n = b.first; n < b.first + b.count; ++n) {
    const auto i = static_cast<size_t>(n);
    r.mass += weight(i);
    mx += weight(i) * s.x[i];
    p += weight(i) * end_velocity(s, dt, i);
  }
  r.centre = mx / r.mass;
  r.velocity = p / r.mass;
  Mat3 inertia = Mat3::Zero();
  Vec3 L = Vec3::Zero();
  for (int n = b.first; n < b.first + b.count; ++n) {
    const auto i = static_cast<size_t>(n);
    const Vec3 d = s.x[i] - r.centre;
    inertia += weight(i) * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
    L += weight(i) * d.cross(end_velocity(s, dt, i) - r.velocity);
  }
  r.inv_inertia = inertia.inverse();
  r.omega = r.inv_inertia * L;
  return r;
}

void PairRestitution::before_solve(const std::vector<std::pair<int, int>>& near, const State& s,
                                   double dt) {
  if (e_ >= 1.0) return;  // e = 1: the elastic result is kept, nothing to record
  for (const auto& [a, b] : near) {
    Episode& ep = episodes_[{a, b}];
    if (ep.started) continue;
    need_whole_bodies();
    ep.a_in = motion_of(a, s, dt);
    ep.b_in = motion_of(b, s, dt);
  }
}

double PairRestitution::apply_rigid_impulse(int body, const BodyRigidPart& motion,
                                            const Vec3& impulse, const Vec3& point, State& s,
                                            double dt) const {
  const NodeRange& b = bodies_[static_cast<size_t>(body)];
  const Vec3 dv_centre = impulse / motion.mass;
  const Vec3 d_omega = motion.inv_inertia * (point - motion.centre).cross(impulse);
  double energy = 0.0;
  for (int n = b.first; n < b.first + b.count; ++n) {
    const auto i = static_cast<size_t>(n);
    const Vec3 dv = dv_centre + d_omega.cross(s.x[i] - motion.centre);
    const Vec3 v = end_velocity(s, dt, i);
    energy += 0.5 * s.m_lumped[i] * ((v + dv).squaredNorm() - v.squaredNorm());
    s.v[i] += dv;
  }
  return energy;
}

// Newton's law for the episode on the rigid motions (eq. R1, R2 of the note).
bool PairRestitution::close(const Episode& ep, int a, int b, State& s, double dt,
                            double& energy_change) {
  if (!(ep.weight > 0.0) || !(ep.impulse.norm() > 0.0)) return true;
  const Vec3 n = ep.impulse.normalized(), P = ep.weighted_point / ep.weight;
  need_whole_bodies();
  const BodyRigidPart A = motion_of(a, s, dt), B = motion_of(b, s, dt);
  const double u_out = n.dot(B.velocity_at(P) - A.velocity_at(P));
  if (u_out < 0.0) return false;  // still approaching: the episode goes on
  const double u_in = n.dot(ep.b_in.velocity_at(P) - ep.a_in.velocity_at(P));
  const double target = e_ * std::max(0.0, -u_in);
  if (u_out <= target) return true;
  // n . (relative velocity at P) per unit impulse along n. A free or pinned rigid body is anchored
  // for the nodal impulse (its nodes are held) but answers with its own mobility: its share of the
  // impulse reaches it as a held impulse (DcrContact::add_held_impulses).
  double K = 0.0;
  for (const auto& [X, anchored] :
       {std::pair{&A, anchored_[static_cast<size_t>(a)] && !mobile_rigid(a, s)},
        std::pair{&B, anchored_[static_cast<size_t>(b)] && !mobile_rigid(b, s)}}) {
    if (anchored) continue;
    const Vec3 r = P - X->centre;
    K += 1.0 / X->mass + n.dot((X->inv_inertia * r.cross(n)).cross(r));
  }
  if (!(K > 0.0)) return true;
  const double j = (u_out - target) / K;
  if (!anchored_[static_cast<size_t>(a)])
    energy_change += apply_rigid_impulse(a, A, j * n, P, s, dt);
  else if (mobile_rigid(a, s))
    rigid_energy_ += rigid_energy_change(A, j * n, P);
  if (!anchored_[static_cast<size_t>(b)])
    energy_change += apply_rigid_impulse(b, B, -j * n, P, s, dt);
  else if (mobile_rigid(b, s))
    rigid_energy_ += rigid_energy_change(B, -j * n, P);
  ++corrections_;
  last_.push_back({a, b, -j * n, P});
  return true;
}

double PairRestitution::after_solve(const std::vector<PairImpulse>& touching,
                                    const std::vector<std::pair<int, int>>& near, State& s,
                                    double dt) {
  last_.clear();
  rigid_energy_ = 0.0;
  if (e_ >= 1.0) return 0.0;
  for (auto& [key, ep] : episodes_) ep.touched = false;
  for (const PairImpulse& t : touching) {
    Episode& ep = episodes_[{t.body_a, t.body_b}];
    const double w = t.impulse_on_b.norm();
    ep.started = ep.touched = true;
    ep.impulse += t.impulse_on_b;
    ep.weighted_point += w * t.point;
    ep.weight += w;
  }
  double energy_change = 0.0;
  for (auto it = episodes_.begin(); it != episodes_.end();) {
    const Episode& ep = it->second;
    const bool held = std::binary_search(near.begin(), near.end(), it->first);
    const bool ended =
        !ep.touched && (!ep.started || (!held && close(ep, it->first.first, it->first.second, s, dt,
                                                       energy_change)));
    it = ended ? episodes_.erase(it) : std::next(it);
  }
  return energy_change;
}

}  // namespace ccm::dcr
