#include "engine/contact/dcr/rigid_partners.hpp"

namespace ccm::dcr {

double RigidPartner::kinetic_energy() const {
  if (inv_mass > 0.0)
    return 0.5 * velocity.squaredNorm() / inv_mass + 0.5 * omega.dot(inv_inertia.inverse() * omega);
  // A pinned body: omega lies along e, and e^T I^-1 e = 1 / J.
  const double w2 = omega.squaredNorm();
  return w2 > 0.0 ? 0.5 * w2 * w2 / omega.dot(inv_inertia * omega) : 0.0;
}

void RigidPartners::reset(const State& s, const std::vector<int>& node_body, size_t n_bodies) {
  partners_.clear();
  node_body_ = &node_body;
  if (s.rigid.empty()) return;
  body_partner_.assign(n_bodies, -1);
  for (const RigidState& r : s.rigid) {
    if (!r.mobile() || static_cast<size_t>(r.body) >= n_bodies) continue;
    body_partner_[static_cast<size_t>(r.body)] = static_cast<int>(partners_.size());
    partners_.push_back(
        {r.inverse_mass, r.inverse_inertia, r.pivot, r.pivot_velocity, r.angular_velocity});
  }
}

RigidRowPart RigidPartners::part_of(const ContactRow& r, const std::vector<Vec3>& x) const {
  RigidRowPart p;
  p.of_node.fill(-1);
  // Eigen's vectors are not zeroed by {}: every sum starts from zero here.
  p.G.fill(Vec3::Zero());
  p.H.fill(Vec3::Zero());
  p.R.fill(Vec3::Zero());
  p.lever.fill(Vec3::Zero());
  if (partners_.empty()) return p;
  for (int a = 0; a < 4; ++a) {
    const int k = partner_of(r.nodes[a]);
    if (k < 0) continue;
    int slot = 0;
    while (slot < p.n && p.partner[static_cast<size_t>(slot)] != k) ++slot;
    if (slot == p.n) p.partner[static_cast<size_t>(p.n++)] = k;
    const auto s = static_cast<size_t>(slot);
    p.of_node[a] = slot;
    p.lever[a] = x[static_cast<size_t>(r.nodes[a])] - partners_[static_cast<size_t>(k)].center;
    p.G[s] += r.grad[a];
    p.H[s] += p.lever[a].cross(r.grad[a]);
    p.B[s] += r.beta[a];
    p.R[s] += r.beta[a] * p.lever[a];
  }
  return p;
}

double RigidPartners::normal_mobility(const RigidRowPart& p) const {
  double W = 0.0;
  for (int s = 0; s < p.n; ++s) {
    const RigidPartner& b = partners_[static_cast<size_t>(p.partner[static_cast<size_t>(s)])];
    const Vec3& G = p.G[static_cast<size_t>(s)];
    const Vec3& H = p.H[static_cast<size_t>(s)];
    W += b.inv_mass * G.squaredNorm() + H.dot(b.inv_inertia * H);
  }
  return W;
}

double RigidPartners::tangential_mobility(const RigidRowPart& p, const ContactRow& r) const {
  double W = 0.0;
  for (int s = 0; s < p.n; ++s) {
    const RigidPartner& b = partners_[static_cast<size_t>(p.partner[static_cast<size_t>(s)])];
    const double B = p.B[static_cast<size_t>(s)];
    const Vec3& R = p.R[static_cast<size_t>(s)];
    double rotation = 0.0;
    for (const Vec3& t : {r.t1, r.t2}) {
      const Vec3 Rt = R.cross(t);
      rotation += 0.5 * Rt.dot(b.inv_inertia * Rt);
    }
    W += b.inv_mass * B * B + rotation;
  }
  return W;
}

Vec3 RigidPartners::slip_per_normal(const RigidRowPart& p) const {
  Vec3 slip = Vec3::Zero();
  for (int s = 0; s < p.n; ++s) {
    const auto i = static_cast<size_t>(s);
    const RigidPartner& b = partners_[static_cast<size_t>(p.partner[i])];
    slip += p.B[i] * b.inv_mass * p.G[i] + (b.inv_inertia * p.H[i]).cross(p.R[i]);
  }
  return slip;
}

void RigidPartners::apply_normal(const RigidRowPart& p, double d_n) {
  for (int s = 0; s < p.n; ++s) {
    RigidPartner& b = partners_[static_cast<size_t>(p.partner[static_cast<size_t>(s)])];
    b.velocity += (d_n * b.inv_mass) * p.G[static_cast<size_t>(s)];
    b.omega += d_n * (b.inv_inertia * p.H[static_cast<size_t>(s)]);
  }
}

void RigidPartners::apply_tangential(const RigidRowPart& p, const Vec3& tangential) {
  for (int s = 0; s < p.n; ++s) {
    RigidPartner& b = partners_[static_cast<size_t>(p.partner[static_cast<size_t>(s)])];
    b.velocity += (p.B[static_cast<size_t>(s)] * b.inv_mass) * tangential;
    b.omega += b.inv_inertia * p.R[static_cast<size_t>(s)].cross(tangential);
  }
}

double RigidPartners::kinetic_energy() const {
  double e = 0.0;
  for (const RigidPartner& b : partners_) e += b.kinetic_energy();
  return e;
}

}  // namespace ccm::dcr
