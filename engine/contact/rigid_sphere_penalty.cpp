#include "engine/contact/rigid_sphere_penalty.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

#include "engine/contact/penalty/surface_quadrature.hpp"
#include "engine/core/parameter_ranges.hpp"
#include "engine/mesh/boundary_surface.hpp"
#include "engine/mesh/model_mesh.hpp"

namespace ccm {
namespace {

// The 3-point rule: engine/contact/penalty/surface_quadrature.hpp.
constexpr std::array<double, 3> shape_at(int k) { return surface_point_weights(k); }

// The stable-step search's safety (see step_bound, docs/contact-time-step.md): a point counts
// when twice the predictor's reach bound could bring it within kRoundOffMargin R of the sphere's
// surface within the step; points closer than that always count.
constexpr double kReachSafety = 2.0;
constexpr double kRoundOffMargin = 1e-6;

// Bulk modulus at the reference state: K = lambda + 2 mu / 3 (Neo-Hookean and linear elastic).
double bulk_modulus(const MaterialParams& m) {
  const Lame l = lame_from(m);
  return l.lambda + 2.0 * l.mu / 3.0;
}

double tet_volume(const std::vector<Vec3>& X, const Tet& t) {
  const Vec3& x0 = X[static_cast<size_t>(t[0])];
  return (X[static_cast<size_t>(t[1])] - x0)
             .cross(X[static_cast<size_t>(t[2])] - x0)
             .dot(X[static_cast<size_t>(t[3])] - x0) /
         6.0;
}

// k_T = s K A^2 / V of every triangle (see the header), on the reference configuration.
std::vector<double> element_stiffness(const ModelMesh& mesh, const std::vector<Triangle>& surface,
                                      double scale) {
  const std::vector<int> owner = owning_tets(mesh.tets, surface);
  std::vector<double> k(surface.size());
  for (size_t i = 0; i < surface.size(); ++i) {
    if (owner[i] < 0)
      throw std::invalid_argument(
          fmt::format("rigid sphere penalty: surface triangle {} is not a face of a tet", i));
    const auto e = static_cast<size_t>(owner[i]);
    const MaterialParams& material =
        mesh.bodies[static_cast<size_t>(mesh.element_body[e])].material;
    const double A = triangle_area(surface[i], mesh.X);
    const double V = tet_volume(mesh.X, mesh.tets[e]);
    k[i] = scale * bulk_modulus(material) * A * A / V;
    if (!(k[i] > 0.0) || !std::isfinite(k[i]))
      throw std::invalid_argument(fmt::format(
          "rigid sphere penalty: element stiffness {} of surface triangle {} is not > 0", k[i], i));
  }
  return k;
}

}  // namespace

RigidSpherePenalty::RigidSpherePenalty(std::vector<Triangle> surface,
                                       RigidSpherePenaltyParams params)
    : RigidSpherePenalty(nullptr, std::move(surface), std::move(params)) {}

RigidSpherePenalty::RigidSpherePenalty(const ModelMesh& mesh, std::vector<Triangle> surface,
                                       RigidSpherePenaltyParams params)
    : RigidSpherePenalty(&mesh, std::move(surface), std::move(params)) {}

RigidSpherePenalty::RigidSpherePenalty(const ModelMesh* mesh, std::vector<Triangle> surface,
                                       RigidSpherePenaltyParams params)
    : ContactModel("rigid_penalty", kForcePhases), params_(std::move(params)) {
  const RigidSphere& s = params_.sphere;
  if (surface.empty()) throw std::invalid_argument("rigid sphere penalty: the surface is empty");
  if (!(s.radius > 0.0) || !std::isfinite(s.radius))
    throw std::invalid_argument("rigid sphere penalty: the radius must be > 0");
  if (!(s.mass > 0.0) || !std::isfinite(s.mass))
    throw std::invalid_argument("rigid sphere penalty: the mass must be > 0");
  if (!(params_.penalty > 0.0) || !std::isfinite(params_.penalty))
    throw std::invalid_argument("rigid sphere penalty: the penalty K_P must be > 0");
  const bool element = params_.penalty_mode == PenaltyMode::element;
  if (element && (!(params_.penalty_scale > 0.0) || !std::isfinite(params_.penalty_scale)))
    throw std::invalid_argument("rigid sphere penalty: the penalty scale s must be > 0");
  if (element && !mesh)
    throw std::invalid_argument("rigid sphere penalty: the element penalty needs the mesh");
  if (!kDampingRange.contains(params_.damping))
    throw std::invalid_argument("rigid sphere penalty: the damping " +
                                kDampingRange.problem(params_.damping));

  if (params_.force_axis) {
    if (!(params_.force_axis->norm() > 0.0))
      throw std::invalid_argument("rigid sphere penalty: the force axis must be non-zero");
    axis_ = params_.force_axis->normalized();
  } else if (s.velocity.norm() > 0.0) {
    axis_ = s.velocity.normalized();
  } else if (params_.gravity.norm() > 0.0) {
    axis_ = params_.gravity.normalized();
  }

  const double zeta = params_.damping;
  damping_bound_factor_ = std::sqrt(1.0 + zeta * zeta) - zeta;

  nodes_ = nodes_of(surface);
  if (nodes_.front() < 0) throw std::invalid_argument("rigid sphere penalty: negative node id");
  const auto local = [&](int global) {
    return static_cast<int>(std::lower_bound(nodes_.begin(), nodes_.end(), global) -
                            nodes_.begin());
  };
  valence_.assign(nodes_.size(), 0.0);
  tris_.reserve(surface.size());
  for (const Triangle& t : surface) {
    const std::array<int, 3> l{local(t[0]), local(t[1]), local(t[2])};
    // Each triangle adds sum_q N_a(q) = kQuadratureNear + 2 kQuadratureFar = 1 to each node.
    for (int a : l) valence_[static_cast<size_t>(a)] += 1.0;
    tris_.push_back(l);
  }
  if (element) {
    unit_ = 1.0;
    point_weight_ = element_stiffness(*mesh, surface, params_.penalty_scale);
    for (double& w : point_weight_) w /= 3.0;  // k_q = k_T / 3: the rule's equal weights
    node_weight_.assign(nodes_.size(), 0.0);
    for (size_t tri = 0; tri < tris_.size(); ++tri)  // sum_q N_a(q) k_q = k_T / 3 per triangle
      for (int a : tris_[tri]) node_weight_[static_cast<size_t>(a)] += point_weight_[tri];
  } else {
    unit_ = params_.penalty;
    point_weight_.assign(tris_.size(), 1.0);
    node_weight_ = valence_;
  }
  const size_t n = nodes_.size();
  f_np1_.assign(n, Vec3::Zero());
  f_n_.assign(n, Vec3::Zero());
  is_touched_np1_.assign(n, 0);
  is_touched_n_.assign(n, 0);
  d2_.assign(3 * tris_.size(), 0.0);
  x_n_.assign(n, Vec3::Zero());

  x_s_ = s.center;
  v_s_ = s.velocity;
  a_s_ = params_.gravity;
  x_s_n_ = x_s_;
}

// ---------------------------------------------------------------------------------------------
// The step: predictor, forces, corrector

void RigidSpherePenalty::begin_step(const State& state, double dt) {
  // The forces of the last evaluation are those at x_n now.
  std::swap(f_n_, f_np1_);
  std::swap(touched_n_, touched_np1_);
  std::swap(is_touched_n_, is_touched_np1_);
  F_s_n_ = F_s_;
  damping_power_n_ = damping_power_;
  for (size_t l = 0; l < nodes_.size(); ++l) x_n_[l] = state.x[static_cast<size_t>(nodes_[l])];

  // x_{n+1} = x_n + dt v_n + dt^2/2 a_n ;  v* = v_n + dt/2 a_n   (eq. 2.27-2.28)
  d2_of_ = nullptr;  // the sphere moves: the distances of add_forces are stale
  x_s_n_ = x_s_;
  v_s_ += 0.5 * dt * a_s_;
  x_s_ += dt * v_s_;
}

// Current positions of the three corners of surface triangle tri.
std::array<Vec3, 3> RigidSpherePenalty::corners(const State& state, size_t tri) const {
  std::array<Vec3, 3> x;
  for (int c = 0; c < 3; ++c)
    x[static_cast<size_t>(c)] = state.x[static_cast<size_t>(
        nodes_[static_cast<size_t>(tris_[tri][static_cast<size_t>(c)])])];
  return x;
}

void RigidSpherePenalty::add_forces(State& state) {
  for (int l : touched_np1_) {
    f_np1_[static_cast<size_t>(l)].setZero();
    is_touched_np1_[static_cast<size_t>(l)] = 0;
  }
  touched_np1_.clear();
  F_s_.setZero();
  penalty_energy_ = 0.0;
  penetration_max_ = 0.0;
  n_active_ = 0;

  const double R = params_.sphere.radius;
  const double R2 = R * R;
  damping_power_ = 0.0;
  for (size_t tri = 0; tri < tris_.size(); ++tri) {
    const std::array<int, 3>& t = tris_[tri];
    const double K = point_stiffness(tri);  // k_q of the triangle's points
    const std::array<Vec3, 3> x = corners(state, tri);
    for (int k = 0; k < 3; ++k) {
      const std::array<double, 3> N = shape_at(k);
      const Vec3 r = N[0] * x[0] + N[1] * x[1] + N[2] * x[2] - x_s_;
      const double d2 = r.squaredNorm();
      d2_[3 * tri + static_cast<size_t>(k)] = d2;
      if (!(d2 < R2)) continue;  // also skips non-finite positions
      const double d = std::sqrt(d2);
      Vec3 n;
      if (d > 1e-12 * R) {
        n = r / d;
      } else {  // the point at the centre: push it into the body, against its outward normal
        n = -(x[1] - x[0]).cross(x[2] - x[0]).normalized();
      }
      const double delta = R - d;
      const Vec3 f_q = point_force(state, tri, k, K, delta, n);  // on the body (eq. 2.5-2.6)
      for (size_t a = 0; a < 3; ++a) {
        const auto l = static_cast<size_t>(t[a]);
        if (!is_touched_np1_[l]) {
          is_touched_np1_[l] = 1;
          touched_np1_.push_back(t[a]);
        }
        f_np1_[l] += N[a] * f_q;
      }
      F_s_ -= f_q;  // on the sphere: equal and opposite
      penalty_energy_ += 0.5 * K * delta * delta;
      penetration_max_ = std::max(penetration_max_, delta);
      ++n_active_;
    }
  }
  for (int l : touched_np1_)
    state.f[static_cast<size_t>(nodes_[static_cast<size_t>(l)])] += f_np1_[static_cast<size_t>(l)];
  a_s_ = F_s_ / params_.sphere.mass + params_.gravity;
  d2_of_ = &state;
  d2_t_ = state.t;
}

// f_q = max(0, k_q delta - c_q u_n) n with c_q = 2 zeta sqrt(k_q mu_q) (see the header).
Vec3 RigidSpherePenalty::point_force(const State& state, size_t tri, int k, double k_q,
                                     double delta, const Vec3& n) {
  const double spring = k_q * delta;
  if (params_.damping == 0.0) return spring * n;
  const std::array<double, 3> N = shape_at(k);
  Vec3 v_q = Vec3::Zero();
  double m_q = 0.0;  // sum_a N_a m_a / s_a: node a's mass shared over its points
  for (size_t a = 0; a < 3; ++a) {
    const auto l = static_cast<size_t>(tris_[tri][a]);
    const auto node = static_cast<size_t>(nodes_[l]);
    v_q += N[a] * state.v[node];
    m_q += N[a] / (valence_[l] * state.inv_m[node]);
  }
  const double m_s = params_.sphere.mass;
  const double mu = m_q * m_s / (m_q + m_s);
  const double c = 2.0 * params_.damping * std::sqrt(k_q * mu);
  const double u_n = n.dot(v_q - v_s_);  // > 0: separating
  const double magnitude = std::max(0.0, spring - c * u_n);
  // The dashpot's share of the force, times the relative velocity: its power (<= 0).
  damping_power_ += (magnitude - spring) * u_n;
  return magnitude * n;
}

void RigidSpherePenalty::end_step(const State& state, double dt) {
  // v_{n+1} = v* + dt/2 a_{n+1}   (eq. 2.31)
  v_s_ += 0.5 * dt * a_s_;

  // Trapezoidal work over the nodes touched at t_n or t_{n+1}; f_n is zero off touched_n_ and
  // f_{n+1} off touched_np1_.
  double w = 0.0;
  const auto add = [&](int l) {
    const auto i = static_cast<size_t>(l);
    const Vec3 dx = state.x[static_cast<size_t>(nodes_[i])] - x_n_[i];
    w += 0.5 * (f_n_[i] + f_np1_[i]).dot(dx);
  };
  for (int l : touched_n_) add(l);
  for (int l : touched_np1_)
    if (!is_touched_n_[static_cast<size_t>(l)]) add(l);
  work_body_ += w;
  work_sphere_ += 0.5 * (F_s_n_ + F_s_).dot(x_s_ - x_s_n_);
  damping_work_ += 0.5 * dt * (damping_power_n_ + damping_power_);
  ledger_ = {
      .work = work_body_, .injected_energy = 0.0, .touching = n_active_ > 0, .failure = failure()};
}

// ---------------------------------------------------------------------------------------------
// Stable step (docs/contact-time-step.md)

double RigidSpherePenalty::node_term(const State& state, int tri) const {
  double k_over_m = 0.0;
  for (int l : tris_[static_cast<size_t>(tri)]) {
    const auto i = static_cast<size_t>(l);
    k_over_m = std::max(k_over_m, node_weight_[i] * state.inv_m[static_cast<size_t>(nodes_[i])]);
  }
  return unit_ * k_over_m;
}

double RigidSpherePenalty::limit_from(double node_term, double weight_sum) const {
  const double omega2 = node_term + unit_ * weight_sum / params_.sphere.mass;
  if (!(omega2 > 0.0)) return std::numeric_limits<double>::infinity();
  return damping_bound_factor_ * 2.0 / std::sqrt(omega2);
}

// Which points count (the proof: docs/contact-time-step.md, "Which points count"). Over a step
// of length h the predictor moves a node by h v_a + h^2/2 a_a and the sphere by h v_s + h^2/2
// a_s, so no point's distance from the sphere's centre falls by more than
//   b(h) = h v_rel + h^2/2 a_rel,  v_rel = |v_s| + max |v_a|,  a_rel = |a_s| + max |a_a|
// (maxima over the surface nodes, at the start of the step). A point counts when it is within
// kRoundOffMargin R of the sphere's surface now, or when kReachSafety b(L) reaches that far for
// the step L being returned, i.e. its reach time tau (kReachSafety b(tau) = gap - kRoundOffMargin
// R) is below L. A counted point brings the nodes of its triangle into the node term. The limit
// is the largest L with L <= f(S(L)), S(L) the points with tau < L and f the bound of a set; f
// falls as S grows, so the points are taken in the order of tau until the next one cannot arrive
// within the current L, or until taking it would cut L below its own tau (then the step ends at
// that tau, before the point can arrive). Far from contact the limit is thus infinite or the
// time the sphere needs to come within reach: the penalty costs nothing until it can act.
ContactStepBound RigidSpherePenalty::step_bound(const State& state, double /*ceiling*/) const {
  // The squared distances of the points from the sphere's centre: those add_forces computed,
  // when they are of this state (the engine asks for the limit of a step after the evaluation
  // that ended the previous one, at the same positions), else afresh.
  if (d2_of_ != &state || d2_t_ != state.t) {
    d2_of_ = nullptr;
    for (size_t tri = 0; tri < tris_.size(); ++tri) {
      const std::array<Vec3, 3> x = corners(state, tri);
      for (int k = 0; k < 3; ++k) {
        const std::array<double, 3> N = shape_at(k);
        d2_[3 * tri + static_cast<size_t>(k)] =
            (N[0] * x[0] + N[1] * x[1] + N[2] * x[2] - x_s_).squaredNorm();
      }
    }
  }

  const double R = params_.sphere.radius;
  const double near = (1.0 + kRoundOffMargin) * R;  // closer than this: the point counts
  const double near2 = near * near;
  double v_max = 0.0, a_max = 0.0;
  for (int n : nodes_) {
    v_max = std::max(v_max, state.v[static_cast<size_t>(n)].squaredNorm());
    a_max = std::max(a_max, state.a[static_cast<size_t>(n)].squaredNorm());
  }
  // The reach bound with its safety factor: kReachSafety b(h) = h v_rel + h^2/2 a_rel.
  const double v_rel = kReachSafety * (v_s_.norm() + std::sqrt(v_max));
  const double a_rel = kReachSafety * (a_s_.norm() + std::sqrt(a_max));

  double A = 0.0;         // max_a kappa_a / m_a over the nodes of the counted points' triangles
  double n_points = 0.0;  // sum of the counted points' weights (per point: their number)
  size_t nearest = d2_.size();  // the closest point that does not count yet
  for (size_t q = 0; q < d2_.size(); ++q) {
    const double d2 = d2_[q];
    if (!(d2 >= near2)) {  // also counts a non-finite distance
      A = std::max(A, node_term(state, static_cast<int>(q / 3)));
      n_points += point_weight_[q / 3];
    } else if (nearest == d2_.size() || d2 < d2_[nearest]) {
      nearest = q;
    }
  }
  double L = limit_from(A, n_points);
  if (nearest == d2_.size() || !(v_rel > 0.0 || a_rel > 0.0)) return {.stiffness_dt = L};
  // tau with b(tau) = s: the root of a_rel/2 tau^2 + v_rel tau - s = 0 in the form that has no
  // cancellation (and is s / v_rel for a_rel = 0, sqrt(2 s / a_rel) for v_rel = 0).
  const auto tau_of = [&](double d2) {
    const double s = std::sqrt(d2) - near;
    return 2.0 * s / (v_rel + std::sqrt(v_rel * v_rel + 2.0 * a_rel * s));
  };

  // The usual cases end here: the nearest point cannot arrive within L (in contact, or far and
  // slow), or taking it would cut L below its tau (far: the step may run until it can arrive).
  double tau = tau_of(d2_[nearest]);
  if (tau >= L) return {.stiffness_dt = L};
  A = std::max(A, node_term(state, static_cast<int>(nearest / 3)));
  n_points += point_weight_[nearest / 3];
  double L_with = limit_from(A, n_points);
  if (L_with <= tau) return {.stiffness_dt = L, .kinematic_dt = tau};
  L = L_with;

  // Approaching contact: take the points that can arrive within L (L only falls from here) in
  // the order of their distance, from a min-heap.
  const double reach = near + L * v_rel + 0.5 * L * L * a_rel;
  scratch_.clear();
  for (size_t q = 0; q < d2_.size(); ++q)
    if (q != nearest && d2_[q] >= near2 && d2_[q] < reach * reach)
      scratch_.emplace_back(d2_[q], static_cast<int>(q / 3));
  const auto farther = std::greater<std::pair<double, int>>();
  std::make_heap(scratch_.begin(), scratch_.end(), farther);
  while (!scratch_.empty()) {
    tau = tau_of(scratch_.front().first);
    if (tau >= L) break;
    std::pop_heap(scratch_.begin(), scratch_.end(), farther);
    A = std::max(A, node_term(state, scratch_.back().second));
    n_points += point_weight_[static_cast<size_t>(scratch_.back().second)];
    scratch_.pop_back();
    L_with = limit_from(A, n_points);
    if (L_with <= tau) return {.stiffness_dt = L, .kinematic_dt = tau};
    L = L_with;
  }
  return {.stiffness_dt = L};
}

// ---------------------------------------------------------------------------------------------
// History

std::vector<std::string> RigidSpherePenalty::history_columns() const {
  std::vector<std::string> c;
  for (const char* q :
       {"sphere_x", "sphere_y", "sphere_z", "sphere_vx", "sphere_vy", "sphere_vz",
        "sphere_kinetic_energy", "contact_force", "contact_force_axis", "penetration_max"})
    c.push_back(params_.name + "." + q);
  return c;
}

void RigidSpherePenalty::append_history(const State& /*state*/, std::vector<double>& row) const {
  row.insert(row.end(), {x_s_.x(), x_s_.y(), x_s_.z(), v_s_.x(), v_s_.y(), v_s_.z(),
                         sphere_kinetic_energy(), F_s_.norm(), F_s_.dot(axis_), penetration_max_});
}

// A surface point at R / 2 from the centre is half a radius deep: the penalty has not stopped
// the sphere, the contact force directions (centre to point) no longer approximate the surface
// normal, and a point that reaches the centre is pushed through the sphere. A working K_P keeps
// the depth to a few per cent of R; half of R is an unambiguous failure, not a tuning limit.
std::string RigidSpherePenalty::failure() const {
  const double limit = kFailureDepth * params_.sphere.radius;
  if (!(penetration_max_ <= limit))
    return fmt::format("penetration {:.4g} m exceeds {} x the sphere radius ({:.4g} m)",
                       penetration_max_, kFailureDepth, params_.sphere.radius);
  return {};
}

}  // namespace ccm
