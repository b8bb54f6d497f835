#include "engine/contact/dcr/contact_impulses.hpp"

#include <algorithm>
#include <cmath>

namespace ccm::dcr {
namespace {

// Tangential: the impulse that stops the sliding of the two contact points (their relative
// tangential velocity `slip`, in the (t1, t2) basis), projected onto the Coulomb disc of the
// normal impulse lambda_n; sets the row's tangential impulses and returns their change (N s),
// with the largest velocity change it makes at the contact points in `change`.
inline Vec3 friction_update(ContactRow& r, const RowInverse& inv, const Vec3& slip, double mu,
                            double lambda_n, double& change) {
  double l1 = r.lambda_t1 - slip.dot(r.t1) * inv.W_t, l2 = r.lambda_t2 - slip.dot(r.t2) * inv.W_t;
  const double bound = mu * r.S * lambda_n, norm2 = l1 * l1 + l2 * l2;
  if (norm2 > bound * bound) {  // sliding: onto the disc (a sticking contact takes no root)
    const double scale = bound / std::sqrt(norm2);
    l1 *= scale;
    l2 *= scale;
  }
  const double d_t1 = l1 - r.lambda_t1, d_t2 = l2 - r.lambda_t2;
  r.lambda_t1 = l1;
  r.lambda_t2 = l2;
  change = std::max(change, std::sqrt(d_t1 * d_t1 + d_t2 * d_t2) * r.W_t);
  return d_t1 * r.t1 + d_t2 * r.t2;
}

// One row's update from the current velocities, applied to its four nodes (distinct: a node
// and a face holding it, or two edges sharing a node, are never a pair); returns the largest
// velocity change of its contact points. The four velocities are read once, updated in place and
// written back once; the normal rate and the slip are both summed from the velocities read, in
// pairs, and the slip then takes the normal update's share, d_n x inv.slip_per_normal (one
// multiply-add instead of a second sum after the update: the two sums no longer wait on each
// other). inv: the row's reciprocal mobilities (RowInverse).
double update_row(ContactRow& r, const RowInverse& inv, const std::vector<double>& inv_m,
                  std::vector<Vec3>& v, double mu) {
  if (!(r.W_n > 0.0)) return 0.0;
  std::array<Vec3, 4> u;
  std::array<double, 4> w;
  for (int a = 0; a < 4; ++a) {
    const auto i = static_cast<size_t>(r.nodes[a]);
    u[a] = v[i];
    w[a] = inv_m[i];
  }
  const bool friction = mu > 0.0 && r.W_t > 0.0;
  // Normal: lambda_n >= 0, complementary to rate_n = grad g . v >= target.
  const double rate =
      (r.grad[0].dot(u[0]) + r.grad[1].dot(u[1])) + (r.grad[2].dot(u[2]) + r.grad[3].dot(u[3]));
  Vec3 slip = Vec3::Zero();  // sum_a beta_a v_a, the contact points' relative velocity
  if (friction)
    slip = (r.beta[0] * u[0] + r.beta[1] * u[1]) + (r.beta[2] * u[2] + r.beta[3] * u[3]);
  const double lambda_n = std::max(0.0, r.lambda_n + (r.target - rate) * inv.W_n);
  const double d_n = lambda_n - r.lambda_n;
  // A contact that stays open (no normal impulse, before or after) carries no friction either
  // (its Coulomb disc has radius 0): nothing changes.
  if (lambda_n == 0.0 && d_n == 0.0 && r.lambda_t1 == 0.0 && r.lambda_t2 == 0.0) return 0.0;
  r.lambda_n = lambda_n;
  for (int a = 0; a < 4; ++a) u[a] += w[a] * d_n * r.grad[a];
  double change = std::abs(d_n) * inv.change_n;
  if (friction) {
    slip += d_n * inv.slip_per_normal;
    const Vec3 tangential = friction_update(r, inv, slip, mu, lambda_n, change);
    for (int a = 0; a < 4; ++a) u[a] += w[a] * r.beta[a] * tangential;
  }
  for (int a = 0; a < 4; ++a) v[static_cast<size_t>(r.nodes[a])] = u[a];
  return change;
}

// update_row for a row with nodes of free rigid bodies (rigid_partners.hpp): their velocities
// are read from the bodies, and the updates change the bodies.
double update_rigid_row(ContactRow& r, const RowInverse& inv, const std::vector<double>& inv_m,
                        std::vector<Vec3>& v, double mu, const RigidRowPart& part,
                        RigidPartners& bodies) {
  if (!(r.W_n > 0.0)) return 0.0;
  std::array<Vec3, 4> u;
  std::array<double, 4> w;
  for (int a = 0; a < 4; ++a) {
    const auto i = static_cast<size_t>(r.nodes[a]);
    u[a] = part.of_node[a] >= 0 ? bodies.velocity(part, a) : v[i];
    w[a] = inv_m[i];  // 0 for a rigid body's node: the body takes its share
  }
  const bool friction = mu > 0.0 && r.W_t > 0.0;
  double rate = 0.0;
  Vec3 slip = Vec3::Zero();
  for (int a = 0; a < 4; ++a) {
    rate += r.grad[a].dot(u[a]);
    slip += r.beta[a] * u[a];
  }
  const double lambda_n = std::max(0.0, r.lambda_n + (r.target - rate) * inv.W_n);
  const double d_n = lambda_n - r.lambda_n;
  if (lambda_n == 0.0 && d_n == 0.0 && r.lambda_t1 == 0.0 && r.lambda_t2 == 0.0) return 0.0;
  r.lambda_n = lambda_n;
  for (int a = 0; a < 4; ++a) u[a] += w[a] * d_n * r.grad[a];
  bodies.apply_normal(part, d_n);
  double change = std::abs(d_n) * inv.change_n;
  if (friction) {
    slip += d_n * inv.slip_per_normal;
    const Vec3 tangential = friction_update(r, inv, slip, mu, lambda_n, change);
    for (int a = 0; a < 4; ++a) u[a] += w[a] * r.beta[a] * tangential;
    bodies.apply_tangential(part, tangential);
  }
  for (int a = 0; a < 4; ++a)
    if (part.of_node[a] < 0) v[static_cast<size_t>(r.nodes[a])] = u[a];
  return change;
}

// Adds the impulse (lambda_n along grad g, tangential along beta) to the row's four nodes.
void apply_impulse(const ContactRow& r, double lambda_n, const Vec3& tangential,
                   const std::vector<double>& inv_m, std::vector<Vec3>& v) {
  for (int a = 0; a < 4; ++a) {
    const auto i = static_cast<size_t>(r.nodes[a]);
    v[i] += inv_m[i] * (lambda_n * r.grad[a] + r.beta[a] * tangential);
  }
}

bool by_nodes(const std::array<int, 4>& a, const std::array<int, 4>& b) { return a < b; }

}  // namespace

// Each row held in the last step starts from its impulses there: the normal multiplier as it
// was, the tangential impulse projected on the new tangents and limited to the Coulomb disc of
// that normal impulse, |lambda_t| <= mu S lambda_n. A row is found by its nodes; when the rows
// are the last solve's, in the same order (same_rows), row k's are last_[k].
void ContactImpulses::warm_start(std::vector<ContactRow>& rows, const std::vector<double>& inv_m,
                                 std::vector<Vec3>& v, double friction, bool same_rows) {
  warm_started_ = 0;
  if (!same_rows) {
    pushing_.clear();
    for (const Remembered& m : last_)
      if (m.lambda_n > 0.0) pushing_.push_back(m);
    std::sort(pushing_.begin(), pushing_.end(),
              [](const Remembered& a, const Remembered& b) { return by_nodes(a.nodes, b.nodes); });
  }
  for (size_t k = 0; k < rows.size(); ++k) {
    ContactRow& r = rows[k];
    if (!(r.W_n > 0.0)) continue;
    const Remembered* m = same_rows ? &last_[k] : nullptr;
    if (!same_rows) {
      const auto it = std::lower_bound(pushing_.begin(), pushing_.end(), r.nodes,
                                       [](const Remembered& x, const std::array<int, 4>& key) {
                                         return by_nodes(x.nodes, key);
                                       });
      if (it != pushing_.end() && it->nodes == r.nodes) m = &*it;
    }
    if (m == nullptr || !(m->lambda_n > 0.0)) continue;
    r.lambda_n = m->lambda_n;
    if (friction > 0.0 && r.W_t > 0.0) {
      double l1 = m->tangential.dot(r.t1), l2 = m->tangential.dot(r.t2);
      const double bound = friction * r.S * r.lambda_n, norm = std::sqrt(l1 * l1 + l2 * l2);
      if (norm > bound) {
        l1 *= bound / norm;
        l2 *= bound / norm;
      }
      r.lambda_t1 = l1;
      r.lambda_t2 = l2;
    }
    const Vec3 tangential = r.lambda_t1 * r.t1 + r.lambda_t2 * r.t2;
    apply_impulse(r, r.lambda_n, tangential, inv_m, v);
    if (partners_ && rigid_index_[k] >= 0) {
      const RigidRowPart& part = rigid_parts_[static_cast<size_t>(rigid_index_[k])];
      partners_->apply_normal(part, r.lambda_n);
      partners_->apply_tangential(part, tangential);
    }
    ++warm_started_;
  }
}

void ContactImpulses::remember(const std::vector<ContactRow>& rows) {
  last_.resize(rows.size());
  for (size_t k = 0; k < rows.size(); ++k) {
    const ContactRow& r = rows[k];
    last_[k] = {r.nodes, r.lambda_n, r.lambda_t1 * r.t1 + r.lambda_t2 * r.t2};
  }
}

// The same rows on the same nodes, in the same order, as the last solve (a resting contact).
bool ContactImpulses::same_rows(const std::vector<ContactRow>& rows) const {
  return linked_.size() == rows.size() &&
         std::equal(
             rows.begin(), rows.end(), linked_.begin(),
             [](const ContactRow& r, const std::array<int, 4>& nodes) { return r.nodes == nodes; });
}

// The rows that share a node with each row (itself included), as a list per node: entries_ holds
// (node, row) sorted by node, and a row's neighbours are the entries of its four nodes. The same
// rows as the last solve's keep their links.
void ContactImpulses::link_rows(const std::vector<ContactRow>& rows, bool same) {
  if (same) return;
  linked_.resize(rows.size());
  for (size_t k = 0; k < rows.size(); ++k) linked_[k] = rows[k].nodes;
  entries_.clear();
  for (size_t k = 0; k < rows.size(); ++k)
    for (int n : rows[k].nodes) entries_.push_back({n, static_cast<int>(k)});
  std::sort(entries_.begin(), entries_.end());
  ranges_.resize(4 * rows.size());
  for (size_t k = 0; k < rows.size(); ++k)
    for (int a = 0; a < 4; ++a) {
      const auto [lo, hi] = std::equal_range(
          entries_.begin(), entries_.end(), std::pair<int, int>{rows[k].nodes[a], -1},
          [](const std::pair<int, int>& x, const std::pair<int, int>& y) {
            return x.first < y.first;
          });
      ranges_[4 * k + static_cast<size_t>(a)] = {static_cast<int>(lo - entries_.begin()),
                                                 static_cast<int>(hi - entries_.begin())};
    }
}

void ContactImpulses::mark_neighbours_dirty(size_t row) {
  for (int a = 0; a < 4; ++a) {
    const auto [lo, hi] = ranges_[4 * row + static_cast<size_t>(a)];
    for (int e = lo; e < hi; ++e)
      dirty_[static_cast<size_t>(entries_[static_cast<size_t>(e)].second)] = 1;
  }
}

// The velocities of a row's nodes at the start of the sweep, the first time the sweep visits them.
void ContactImpulses::remember_velocities(const ContactRow& r, const std::vector<Vec3>& v) {
  for (int n : r.nodes) {
    const auto i = static_cast<size_t>(n);
    if (stamp_[i] == epoch_) continue;
    stamp_[i] = epoch_;
    start_.emplace_back(n, v[i]);
  }
}

// The largest change of a node's velocity over the sweep.
double ContactImpulses::largest_change(const std::vector<Vec3>& v) const {
  double worst2 = 0.0;
  for (const auto& [n, v0] : start_)
    worst2 = std::max(worst2, (v[static_cast<size_t>(n)] - v0).squaredNorm());
  return std::sqrt(worst2);
}

void ContactImpulses::attach_rigid(std::vector<ContactRow>& rows, const std::vector<Vec3>& x) {
  rigid_index_.assign(rows.size(), -1);
  rigid_parts_.clear();
  body_rows_.assign(static_cast<size_t>(partners_->size()), {});
  for (size_t k = 0; k < rows.size(); ++k) {
    ContactRow& r = rows[k];
    const RigidRowPart part = partners_->part_of(r, x);
    if (part.n == 0) continue;
    const bool inert = !(r.S > 0.0);  // make_row left it without a normal
    if (inert) continue;
    r.W_n += partners_->normal_mobility(part);
    r.W_t += partners_->tangential_mobility(part, r);
    rigid_index_[k] = static_cast<int>(rigid_parts_.size());
    rigid_parts_.push_back(part);
    for (int s = 0; s < part.n; ++s)
      body_rows_[static_cast<size_t>(part.partner[static_cast<size_t>(s)])].push_back(
          static_cast<int>(k));
  }
}

void ContactImpulses::mark_body_rows_dirty(size_t row) {
  const RigidRowPart& part = rigid_parts_[static_cast<size_t>(rigid_index_[row])];
  for (int s = 0; s < part.n; ++s)
    for (int k : body_rows_[static_cast<size_t>(part.partner[static_cast<size_t>(s)])])
      dirty_[static_cast<size_t>(k)] = 1;
}

// The patches' normal rows solved directly (patch_solve.hpp), the free rigid bodies' rows held;
// every row is visited again by the next sweep.
void ContactImpulses::solve_patches(std::vector<ContactRow>& rows, const std::vector<double>& inv_m,
                                    std::vector<Vec3>& v, double limit) {
  held_.assign(rows.size(), 0);
  if (partners_)
    for (size_t k = 0; k < rows.size(); ++k) held_[k] = rigid_index_[k] >= 0;
  patches_.solve(rows, inv_m, v, entries_, held_, limit);
  std::fill(dirty_.begin(), dirty_.end(), 1);
}

ImpulseSolve ContactImpulses::solve(std::vector<ContactRow>& rows, const std::vector<int>& order,
                                    const std::vector<double>& inv_m, std::vector<Vec3>& v,
                                    const ImpulseSettings& settings, RigidPartners* partners,
                                    const std::vector<Vec3>* x) {
  partners_ = partners && !partners->empty() && x ? partners : nullptr;
  if (partners_) attach_rigid(rows, *x);
  // Reference speed: the fastest contact node (a solve that moves no node by more than
  // tolerance x v_ref has converged).
  double v_ref = 0.0;
  for (const ContactRow& r : rows)
    for (int n : r.nodes) v_ref = std::max(v_ref, v[static_cast<size_t>(n)].norm());
  // With rigid partners, the rigid rows' velocities are the bodies': the reference speed takes
  // them in as well.
  if (partners_)
    for (int b = 0; b < partners_->size(); ++b)
      v_ref = std::max(v_ref, (*partners_)[b].velocity.norm());
  const double limit =
      std::max(settings.tolerance * std::max(v_ref, 1e-300), settings.velocity_floor);
  const bool same = same_rows(rows);
  if (settings.warm_start) warm_start(rows, inv_m, v, settings.friction, same);
  link_rows(rows, same);
  inverse_.resize(rows.size());
  for (size_t k = 0; k < rows.size(); ++k) {
    const ContactRow& r = rows[k];
    if (!(r.W_n > 0.0)) continue;
    Vec3 slip_per_normal = Vec3::Zero();
    for (int a = 0; a < 4; ++a)
      slip_per_normal += r.beta[a] * inv_m[static_cast<size_t>(r.nodes[a])] * r.grad[a];
    if (partners_ && rigid_index_[k] >= 0)
      slip_per_normal +=
          partners_->slip_per_normal(rigid_parts_[static_cast<size_t>(rigid_index_[k])]);
    inverse_[k] = {1.0 / r.W_n, r.W_t > 0.0 ? 1.0 / r.W_t : 0.0, r.W_n / r.S, slip_per_normal};
  }
  dirty_.assign(rows.size(), 1);
  // The patch solve holds the friction impulses: with friction the sweeps iterate them anyway,
  // and there it cost more than it saved (a frictional crush, 7 December 2026: 12 % more time
  // per step once per solve, 120 % every 10 sweeps). Without friction it runs every
  // direct_after sweeps: the rows one solve closed join the next (crush family, 7 December 2026:
  // 1,045 -> 31 and 1,770 -> 115 solves at the cap, the same time per step).
  const bool direct = settings.direct_after > 0 && settings.friction == 0.0;
  ImpulseSolve out{0, rows.empty()};
  visits_ = 0;
  if (stamp_.size() < v.size()) stamp_.resize(v.size(), -1);
  while (out.sweeps < settings.max_iterations) {
    const int sweep = out.sweeps;
    const bool forward = sweep % 2 == 0;
    start_.clear();
    ++epoch_;
    double rigid_change = 0.0;
    for (size_t j = 0; j < order.size(); ++j) {
      const auto k = static_cast<size_t>(order[forward ? j : order.size() - 1 - j]);
      if (!dirty_[k]) continue;
      dirty_[k] = 0;
      ++visits_;
      remember_velocities(rows[k], v);
      if (partners_ && rigid_index_[k] >= 0) {
        const double change =
            update_rigid_row(rows[k], inverse_[k], inv_m, v, settings.friction,
                             rigid_parts_[static_cast<size_t>(rigid_index_[k])], *partners_);
        rigid_change = std::max(rigid_change, change);
        if (change > limit) {
          mark_neighbours_dirty(k);
          mark_body_rows_dirty(k);
        }
        continue;
      }
      if (update_row(rows[k], inverse_[k], inv_m, v, settings.friction) > limit)
        mark_neighbours_dirty(k);
    }
    ++out.sweeps;
    // A rigid row's contact points move with a body the nodes' record does not hold: its own
    // largest change counts too.
    const double worst = std::max(largest_change(v), rigid_change);
    if (worst <= limit) {
      out.converged = true;
      break;
    }
    if (direct && out.sweeps % settings.direct_after == 0 && out.sweeps < settings.max_iterations)
      solve_patches(rows, inv_m, v, limit);
  }
  remember(rows);
  return out;
}

}  // namespace ccm::dcr
