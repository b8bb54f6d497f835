#include "engine/contact/dcr/dcr_contact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "engine/contact/dcr/ccd.hpp"

namespace ccm::dcr {
namespace {

// Tolerance of the barycentric / edge-parameter inclusion tests in the CCD.
constexpr double kInclusionTolerance = 1e-6;

double shortest_edge(const SurfaceFeatures& f, const std::vector<Vec3>& X) {
  double h = std::numeric_limits<double>::infinity();
  for (const auto& e : f.edges) h = std::min(h, (X[e[1]] - X[e[0]]).norm());
  return h;
}

}  // namespace

DcrContact::DcrContact(const ModelMesh& mesh, DcrSettings settings,
                       const std::vector<int>& fixed_nodes)
    : settings_(std::move(settings)), features_(make_surface_features(mesh, settings_.surfaces)) {
  if (settings_.restitution < 0.0 || settings_.restitution > 1.0)
    throw std::invalid_argument("dcr: restitution must lie in [0, 1]");
  if (settings_.friction < 0.0) throw std::invalid_argument("dcr: friction must be >= 0");
  inv_m_.assign(mesh.X.size(), 0.0);  // filled from the state's masses at the first step
  for (int n : fixed_nodes) inv_m_[static_cast<size_t>(n)] = -1.0;  // marker: never moves
  min_edge_ = shortest_edge(features_, mesh.X);
  // Kept gap after projection: far below the mesh size, far above round-off.
  separation_ = 1e-4 * min_edge_;
  v_end_.assign(mesh.X.size(), Vec3::Zero());
  count_.assign(mesh.X.size(), 0);
}

std::string DcrContact::failure() const {
  const double limit = kFailurePenetration * min_edge_;
  if (!(residual_ <= limit))  // also NaN
    return fmt::format(
        "residual penetration {:.4g} m exceeds {:.4g} m ({} x the shortest surface "
        "edge {:.4g} m) after {} iterations",
        residual_, limit, kFailurePenetration, min_edge_, settings_.max_iterations);
  return {};
}

void DcrContact::begin_step(const State& state, double /*dt*/) {
  if (x_n_.empty()) {  // first step: masses are known now
    for (size_t i = 0; i < inv_m_.size(); ++i)
      inv_m_[i] = inv_m_[i] < 0.0 ? 0.0 : 1.0 / state.m_lumped[i];
  }
  x_n_ = state.x;
}

// g = sign * signed volume (contact-method.md 1.1); returns it.
double DcrContact::constraint_value(const Constraint& c, const std::vector<Vec3>& x) const {
  const auto& n = c.nodes;
  const double v = c.node_face ? node_face_volume(x[n[0]], x[n[1]], x[n[2]], x[n[3]])
                               : edge_edge_volume(x[n[0]], x[n[1]], x[n[2]], x[n[3]]);
  return c.sign * v;
}

// grad g into grad[4]; returns the scale k with g / k a signed distance (A/3 for a node and a
// face of area A; |e1 x e2| / 6 for two edges).
double DcrContact::constraint_gradient(const Constraint& c, const std::vector<Vec3>& x,
                                       Vec3 grad[4]) const {
  const auto& n = c.nodes;
  double k;
  if (c.node_face) {
    node_face_volume_gradient(x[n[0]], x[n[1]], x[n[2]], x[n[3]], grad);
    k = grad[0].norm();  // grad_p g = (1/6)(b - a) x (c - a) = (A/3) n
  } else {
    edge_edge_volume_gradient(x[n[0]], x[n[1]], x[n[2]], x[n[3]], grad);
    k = (x[n[1]] - x[n[0]]).cross(x[n[3]] - x[n[2]]).norm() / 6.0;
  }
  for (int a = 0; a < 4; ++a) grad[a] *= c.sign;
  return k;
}

// Without self-contact, bodies whose swept surface boxes do not overlap cannot touch: the
// broad phase is skipped (a scene pays for the search only while bodies are close).
bool DcrContact::bodies_may_touch(const State& s) const {
  if (settings_.self_contact) return true;
  std::vector<Eigen::AlignedBox3d> boxes;
  for (size_t i = 0; i < features_.nodes.size(); ++i) {
    const auto body = static_cast<size_t>(features_.node_body[i]);
    if (boxes.size() <= body) boxes.resize(body + 1);
    const auto n = static_cast<size_t>(features_.nodes[i]);
    boxes[body].extend(x_n_[n]);
    boxes[body].extend(s.x[n]);
  }
  for (auto& b : boxes)
    if (!b.isEmpty()) {
      b.min().array() -= 2.0 * separation_;
      b.max().array() += 2.0 * separation_;
    }
  for (size_t a = 0; a < boxes.size(); ++a)
    for (size_t b = a + 1; b < boxes.size(); ++b)
      if (!boxes[a].isEmpty() && !boxes[b].isEmpty() && boxes[a].intersects(boxes[b])) return true;
  return false;
}

void DcrContact::detect(const State& s) {
  constraints_.clear();
  if (!bodies_may_touch(s)) return;
  broad_phase_.find(features_, x_n_, s.x, 2.0 * separation_, settings_.self_contact, candidates_);
  const std::vector<Vec3>& x0 = x_n_;
  const std::vector<Vec3>& x1 = s.x;
  for (const NodeFaceCandidate& nf : candidates_.node_face) {
    const int p = features_.nodes[static_cast<size_t>(nf.node)];
    const Triangle& t = features_.faces[static_cast<size_t>(nf.face)];
    // Only a node arriving from the outward side is held out (g(x_n) >= 0).
    if (node_face_volume(x0[p], x0[t[0]], x0[t[1]], x0[t[2]]) < 0.0) continue;
    if (!node_face_ccd(x0[p], x0[t[0]], x0[t[1]], x0[t[2]], x1[p], x1[t[0]], x1[t[1]], x1[t[2]],
                       kInclusionTolerance))
      continue;
    constraints_.push_back({{p, t[0], t[1], t[2]}, true, 1.0, 0.0, 0.0});
  }
  for (const EdgeEdgeCandidate& ee : candidates_.edge_edge) {
    const auto& ea = features_.edges[static_cast<size_t>(ee.edge_a)];
    const auto& eb = features_.edges[static_cast<size_t>(ee.edge_b)];
    if (!edge_edge_ccd(x0[ea[0]], x0[ea[1]], x0[eb[0]], x0[eb[1]], x1[ea[0]], x1[ea[1]], x1[eb[0]],
                       x1[eb[1]], kInclusionTolerance))
      continue;
    // The admissible side is the one the edges started on (the thesis's orientation tag).
    const double g0 = edge_edge_volume(x0[ea[0]], x0[ea[1]], x0[eb[0]], x0[eb[1]]);
    constraints_.push_back({{ea[0], ea[1], eb[0], eb[1]}, false, g0 >= 0.0 ? 1.0 : -1.0, 0.0, 0.0});
  }
}

// Relaxed Jacobi: every constraint proposes a multiplier step along M^-1 grad g from the same
// state (so the order of the constraints does not matter); the step is scaled by 1 / (the
// largest number of proposing constraints at any of its nodes), so shared nodes are not
// over-corrected, and then applied whole to all four nodes, so that sum m dv = step * sum grad g
// = 0 and linear and angular momentum are conserved exactly (contact-method.md 1.2).
void DcrContact::apply_relaxed(std::vector<Vec3>& target) {
  for (size_t k = 0; k < constraints_.size(); ++k)
    if (steps_[k] != 0.0)
      for (int n : constraints_[k].nodes) ++count_[static_cast<size_t>(n)];
  for (size_t k = 0; k < constraints_.size(); ++k) {
    if (steps_[k] == 0.0) continue;
    const Constraint& c = constraints_[k];
    int shared = 1;
    for (int n : c.nodes) shared = std::max(shared, count_[static_cast<size_t>(n)]);
    steps_[k] /= shared;
    for (int a = 0; a < 4; ++a) {
      const auto n = static_cast<size_t>(c.nodes[a]);
      target[n] += steps_[k] * inv_m_[n] * grads_[k][a];
    }
  }
  for (const Constraint& c : constraints_)
    for (int n : c.nodes) count_[static_cast<size_t>(n)] = 0;
}

double DcrContact::mobility(const Constraint& c, const std::array<Vec3, 4>& grad) const {
  double W = 0.0;  // W = grad g^T M^-1 grad g
  for (int a = 0; a < 4; ++a) W += grad[a].squaredNorm() * inv_m_[static_cast<size_t>(c.nodes[a])];
  return W;
}

// Mass-weighted projection onto g >= separation * k (contact-method.md 1.2): Newton steps
// lambda = (target - g) / W, relaxed Jacobi sweeps until every constraint holds.
void DcrContact::project_positions(State& s) {
  x_start_.clear();
  for (const Constraint& c : constraints_)
    for (int n : c.nodes) x_start_.push_back(s.x[static_cast<size_t>(n)]);
  steps_.assign(constraints_.size(), 0.0);
  grads_.resize(constraints_.size());
  for (int it = 0; it < settings_.max_iterations; ++it) {
    double worst = 0.0;
    for (size_t k = 0; k < constraints_.size(); ++k) {
      const Constraint& c = constraints_[k];
      steps_[k] = 0.0;
      const double scale = constraint_gradient(c, s.x, grads_[k].data());
      const double gap = separation_ * scale - constraint_value(c, s.x);
      const double W = mobility(c, grads_[k]);
      if (gap <= 0.0 || !(W > 0.0)) continue;
      worst = std::max(worst, gap / scale);
      steps_[k] = gap / W;
    }
    if (worst <= 1e-3 * separation_) break;
    apply_relaxed(s.x);
  }
  // Work of the projection against the current forces f = m a (thesis eq. 2.21), each moved
  // node counted once.
  size_t k = 0;
  for (const Constraint& c : constraints_)
    for (int n : c.nodes) {
      const auto i = static_cast<size_t>(n);
      const Vec3& before = x_start_[k++];
      if (count_[i] != 0) continue;
      count_[i] = 1;
      work_ -= s.m_lumped[i] * s.a[i].dot(s.x[i] - before);
    }
  residual_ = 0.0;
  Vec3 grad[4];
  for (const Constraint& c : constraints_) {
    for (int n : c.nodes) count_[static_cast<size_t>(n)] = 0;
    const double scale = constraint_gradient(c, s.x, grad);
    residual_ = std::max(residual_, -constraint_value(c, s.x) / scale);
  }
}

void DcrContact::correct(State& s, double dt) {
  detect(s);
  last_impulse_ = 0.0;
  if (constraints_.empty()) {
    residual_ = 0.0;
    return;
  }
  project_positions(s);
  exchange_momentum(s, dt);
}

// Normal momentum exchange on the end-of-step velocity v_end = v* + dt/2 a_{n+1}: each
// approaching constraint (dg/dt = grad g . v < 0) is driven to dg/dt = -e (dg/dt)_0 (eq. 2.26
// for e = 1; e = 0 removes the approach) with non-negative accumulated multipliers, by relaxed
// Jacobi sweeps; then friction; the change is added to v* so the velocity correction lands on it.
void DcrContact::exchange_momentum(State& s, double dt) {
  std::vector<Vec3>& v_end = v_end_;  // only the constrained nodes are read or written
  v_before_.clear();
  for (const Constraint& c : constraints_)
    for (int n : c.nodes) {
      const auto i = static_cast<size_t>(n);
      v_end[i] = s.v[i] + 0.5 * dt * s.a[i];
      v_before_.push_back(v_end[i]);
    }
  for (size_t k = 0; k < constraints_.size(); ++k) {
    Constraint& c = constraints_[k];
    constraint_gradient(c, s.x, grads_[k].data());
    c.approach_rate = rate_of(c, grads_[k], v_end);
    c.impulse = 0.0;
  }
  const double e = settings_.restitution;
  for (int it = 0; it < settings_.max_iterations; ++it) {
    double worst = 0.0, scale = 0.0;
    for (size_t k = 0; k < constraints_.size(); ++k) {
      Constraint& c = constraints_[k];
      steps_[k] = 0.0;
      if (c.approach_rate >= 0.0) continue;
      const double W = mobility(c, grads_[k]);
      if (!(W > 0.0)) continue;
      const double target = -e * c.approach_rate, rate = rate_of(c, grads_[k], v_end);
      const double new_impulse = std::max(0.0, c.impulse + (target - rate) / W);
      steps_[k] = new_impulse - c.impulse;
      if (rate < target || c.impulse > 0.0) worst = std::max(worst, std::abs(target - rate));
      scale = std::max(scale, -c.approach_rate);
    }
    if (worst <= 1e-9 * scale) break;
    apply_relaxed(v_end);
    for (size_t k = 0; k < constraints_.size(); ++k) constraints_[k].impulse += steps_[k];
  }
  if (settings_.friction > 0.0) apply_friction(s, v_end);

  // Kinetic energy change of the jump = work of the contact impulses; then v* += dv.
  size_t k = 0;
  for (const Constraint& c : constraints_) {
    last_impulse_ += c.impulse;
    for (int n : c.nodes) {
      const auto i = static_cast<size_t>(n);
      const Vec3& before = v_before_[k++];
      if (count_[i] != 0) continue;  // a node shared by constraints is applied once
      count_[i] = 1;
      work_ += 0.5 * s.m_lumped[i] * (v_end[i].squaredNorm() - before.squaredNorm());
      s.v[i] += v_end[i] - before;
    }
  }
  for (const Constraint& c : constraints_)
    for (int n : c.nodes) count_[static_cast<size_t>(n)] = 0;
}

double DcrContact::rate_of(const Constraint& c, const std::array<Vec3, 4>& grad,
                           const std::vector<Vec3>& v) const {
  double rate = 0.0;  // dg/dt = grad g . v
  for (int a = 0; a < 4; ++a) rate += grad[a].dot(v[static_cast<size_t>(c.nodes[a])]);
  return rate;
}

// Pairwise Coulomb friction in the contact frame (contact-method.md 1.3): the tangential
// relative velocity u_t of the two contact points is reduced by j_t = min(mu j_n, m_eff |u_t|),
// one relaxed Jacobi sweep, applied whole to both sides (momentum exact).
void DcrContact::apply_friction(const State& s, std::vector<Vec3>& v_end) {
  tangent_.assign(constraints_.size(), Vec3::Zero());
  for (size_t k = 0; k < constraints_.size(); ++k) {
    const Constraint& c = constraints_[k];
    steps_[k] = 0.0;
    if (c.impulse <= 0.0) continue;
    // All four gradients are parallel to the contact normal n. The contact points are
    // sum beta_a x_a with beta_a = grad_a g . n / S, S normalising the first side's weights to
    // 1 (node-face: the node; edge-edge: the first edge); j_n = impulse * S.
    std::array<Vec3, 4> grad;
    constraint_gradient(c, s.x, grad.data());
    int biggest = 0;
    for (int a = 1; a < 4; ++a)
      if (grad[a].squaredNorm() > grad[biggest].squaredNorm()) biggest = a;
    const Vec3 n = grad[biggest].normalized();
    double S = 0.0;
    for (int a = 0; a < (c.node_face ? 1 : 2); ++a) S += std::abs(grad[a].dot(n));
    if (!(S > 0.0)) continue;
    double inv_m_eff = 0.0;
    Vec3 u = Vec3::Zero();
    for (int a = 0; a < 4; ++a) {
      const auto i = static_cast<size_t>(c.nodes[a]);
      const double beta = grad[a].dot(n) / S;
      inv_m_eff += beta * beta * inv_m_[i];
      u += beta * v_end[i];
      grads_[k][a] = beta * n;  // reused below as the tangential direction's weights
    }
    const Vec3 u_t = u - u.dot(n) * n;
    const double speed = u_t.norm();
    if (!(speed > 0.0) || !(inv_m_eff > 0.0)) continue;
    tangent_[k] = u_t / speed;
    steps_[k] = -std::min(settings_.friction * c.impulse * S, speed / inv_m_eff);
    for (int a = 0; a < 4; ++a) grads_[k][a] = grads_[k][a].dot(n) * tangent_[k];
  }
  apply_relaxed(v_end);
}

// No surface may move, relative to another, more than step_fraction of the shortest surface
// edge in one step: the projection then stays a small correction, and the end-of-step
// configuration of a pair stays close to the linear path the CCD assumed.
double DcrContact::stable_dt_limit(const State& state) const {
  double v_max = 0.0;
  for (int n : features_.nodes) v_max = std::max(v_max, state.v[static_cast<size_t>(n)].norm());
  if (!(v_max > 0.0)) return std::numeric_limits<double>::infinity();
  return settings_.step_fraction * min_edge_ / (2.0 * v_max);
}

std::vector<std::string> DcrContact::history_columns() const {
  return {"contact.active", "contact.normal_impulse", "contact.work",
          "contact.residual_penetration"};
}

void DcrContact::append_history(const State& /*s*/, std::vector<double>& row) const {
  row.insert(row.end(),
             {static_cast<double>(constraints_.size()), last_impulse_, work_, residual_});
}

}  // namespace ccm::dcr
