// Free and pinned rigid bodies as partners of the DCR velocity solve (docs/rigid-bodies.md,
// "Contact"). A pinned body is the same partner about its pin: 1/m = 0, I^-1 = e e^T / J and c
// a point of the axis, which does not move (RB.10).
//
// The DCR holds every rigid body's nodes (inv_m = 0: the contact never moves them by a nodal
// mass). A free rigid body still answers an impulse: a row whose nodes a include nodes of body b
// (centre c, velocity V, angular velocity w, 1/m, I^-1 in world axes) reads their velocities as
// V + w x r_a (r_a = x_a - c), and its normal update d_n changes the body by
//   dV = d_n G / m,   dw = d_n I^-1 H,   G = sum_{a in b} grad_a,  H = sum_{a in b} r_a x grad_a,
// so the row's mobility gains |G|^2 / m + H^T I^-1 H (the 1/m + (r x n)^T I^-1 (r x n) of a
// point contact). A tangential update lambda_t at the contact-point weights beta_a changes it by
// (sum beta_a) lambda_t / m and I^-1 (sum beta_a r_a) x lambda_t; the tangential mobility gains the
// mean over the two tangents of the same form. Every row impulse has its opposite on the other
// side, so linear and angular momentum stay exact; the rows of one body are coupled through it.
#pragma once

#include <array>
#include <vector>

#include "engine/contact/dcr/contact_row.hpp"
#include "engine/core/state.hpp"

namespace ccm::dcr {

struct RigidPartner {
  double inv_mass = 0.0;
  Mat3 inv_inertia = Mat3::Zero();  // world axes
  Vec3 center = Vec3::Zero(), velocity = Vec3::Zero(), omega = Vec3::Zero();
  Vec3 velocity_at(const Vec3& x) const { return velocity + omega.cross(x - center); }
  double kinetic_energy() const;
};

// A row's part on free rigid bodies: at most two bodies (one per side).
struct RigidRowPart {
  int n = 0;                     // bodies in the row
  std::array<int, 2> partner{};  // indices into RigidPartners
  std::array<int, 4> of_node{};  // per row node: 0 or 1 (its body in `partner`), -1: not rigid
  std::array<Vec3, 4> lever{};   // r_a = x_a - c of the rigid nodes
  std::array<Vec3, 2> G{}, H{};  // normal: sum grad_a, sum r_a x grad_a
  std::array<double, 2> B{};     // tangential: sum beta_a
  std::array<Vec3, 2> R{};       // tangential: sum beta_a r_a
};

class RigidPartners {
 public:
  // From the state's mobile rigid bodies (RigidState::mobile: free and pinned); node_body maps a node
  // to its body (of n_bodies). Empty when the state has none.
  void reset(const State& s, const std::vector<int>& node_body, size_t n_bodies);
  bool empty() const { return partners_.empty(); }
  // The partner of node n, or -1.
  int partner_of(int n) const {
    return partners_.empty()
               ? -1
               : body_partner_[static_cast<size_t>(node_body_->at(static_cast<size_t>(n)))];
  }
  RigidPartner& operator[](int k) { return partners_[static_cast<size_t>(k)]; }
  const RigidPartner& operator[](int k) const { return partners_[static_cast<size_t>(k)]; }
  int size() const { return static_cast<int>(partners_.size()); }

  // The row's rigid part from the current positions; n == 0 when no node is a free body's.
  RigidRowPart part_of(const ContactRow& r, const std::vector<Vec3>& x) const;
  // What the rigid part adds to the row's mobilities W_n and W_t.
  double normal_mobility(const RigidRowPart& p) const;
  double tangential_mobility(const RigidRowPart& p, const ContactRow& r) const;
  // The velocity of row node a (rigid), and the changes of a normal and a tangential update.
  Vec3 velocity(const RigidRowPart& p, int a) const {
    const RigidPartner& b =
        partners_[static_cast<size_t>(p.partner[static_cast<size_t>(p.of_node[a])])];
    return b.velocity + b.omega.cross(p.lever[a]);
  }
  // The change of sum_a beta_a v_a (the contact points' relative velocity) per unit normal
  // update, from the rigid part: B dV + dw x R per body.
  Vec3 slip_per_normal(const RigidRowPart& p) const;
  void apply_normal(const RigidRowPart& p, double d_n);
  void apply_tangential(const RigidRowPart& p, const Vec3& tangential);
  double kinetic_energy() const;

 private:
  std::vector<RigidPartner> partners_;
  std::vector<int> body_partner_;  // per body: partner index or -1
  const std::vector<int>* node_body_ = nullptr;
};

}  // namespace ccm::dcr
