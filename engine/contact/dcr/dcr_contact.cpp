#include "engine/contact/dcr/dcr_contact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "engine/contact/dcr/ccd.hpp"
#include "engine/contact/dcr/ccd_prefilter.hpp"
#include "engine/contact/dcr/step_limit.hpp"
#include "engine/core/parameter_ranges.hpp"

namespace ccm::dcr {
namespace {

// Tolerance of the barycentric / edge-parameter inclusion tests in the CCD.
constexpr double kInclusionTolerance = 1e-6;

// The position projection's dead band: a constraint within this x the kept separation of it
// is met (project_positions).
constexpr double kDeadBand = 1e-3;

// Velocity solve converged when no contact changes a velocity by more than this x the fastest
// contact node, or by more than kVelocityFloor x the kept separation per step (velocity_floor),
// a change that moves a node over the step by less than 4e-3 of the separation. A resting
// contact's fastest node moves at about g dt, and the relative limit alone then asks the sweeps
// for changes far below anything the positions show (docs/hard-scenes.md). The floor was the
// dead band (1e-3) until the resting aim took a margin above it (kRestingAim): the sweeps to
// 1e-3 cost 8 % of a resting step more for a landing the aim's margin already covers.
constexpr double kVelocityTolerance = 1e-6;
constexpr double kVelocityFloor = 4e-3;

// The pair distance cache re-anchors when a node moved this x the shortest edge from its anchor
// (pair_distance_cache.hpp): far above a resting contact's motion, far below an element.
constexpr double kReanchorFraction = 0.1;

// A resting contact's velocity target aims the next predicted position at this x the kept
// separation (make_row): a little above it, so that the solve's tolerance (kVelocityFloor, a
// landing up to about 4e-3 of the separation short), the predictor's rounding and the
// constraint's curvature leave it above the projection's dead band, and so little above that
// the work of lifting a body onto it is negligible (2 x, tried first, lifted the stacked blocks
// of the [hard] test by one separation more: +7 % of that small scene's energy scale).
constexpr double kRestingAim = 1.005;

// How far a projection may move a node, as a fraction of the height of the tets around it,
// before the next step is shortened (eq. PJ.1, docs/time-step.md, "After a contact correction"):
//     dt_next <= dt sqrt(kProjectionJump / (max |dx_proj| / h_e))
// The predictor presses pressed surfaces together by dt^2/2 of their acceleration, so the next
// projection's move scales with dt^2 and this brings it to kProjectionJump h_e. A projection
// that moves nodes by a sizeable part of their tets every step leaves the step's energy measure
// unbalanced (a wall one flat tet thick crushed at 8 m/s, docs/hard-scenes.md: 5.2 % without the
// bound, 0.33 % with it); a resting or Hertz contact moves them by 1e-4 of h_e or less, and this
// bound is far above its step.
constexpr double kProjectionJump = 0.03;

// Tolerance of the "projection inside the face" test of a persistent contact (barycentric).
constexpr double kPersistentTolerance = 1e-6;

// The bodies that own a feature of the contact surfaces, sorted.
std::vector<int> contact_bodies(const SurfaceFeatures& f) {
  std::vector<int> bodies(f.node_body.begin(), f.node_body.end());
  std::sort(bodies.begin(), bodies.end());
  bodies.erase(std::unique(bodies.begin(), bodies.end()), bodies.end());
  return bodies;
}

// Whether each body holds a fixed node (anchored bodies get no restitution impulse).
std::vector<bool> anchored_bodies(const ModelMesh& mesh, const std::vector<int>& fixed_nodes) {
  std::vector<bool> anchored(mesh.bodies.size(), false);
  for (int n : fixed_nodes)
    for (size_t b = 0; b < mesh.bodies.size(); ++b)
      if (n >= mesh.bodies[b].first_node && n < mesh.bodies[b].first_node + mesh.bodies[b].n_nodes)
        anchored[b] = true;
  return anchored;
}

// Whether the orthogonal projection of p onto the plane of (a, b, c) lies in the triangle
// (barycentric weights >= -tol).
bool projects_inside(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, double tol) {
  const Vec3 e1 = b - a, e2 = c - a, r = p - a;
  const double d11 = e1.dot(e1), d12 = e1.dot(e2), d22 = e2.dot(e2);
  const double r1 = r.dot(e1), r2 = r.dot(e2), det = d11 * d22 - d12 * d12;
  if (!(det > 0.0)) return false;
  const double wb = (d22 * r1 - d12 * r2) / det, wc = (d11 * r2 - d12 * r1) / det;
  return wb >= -tol && wc >= -tol && 1.0 - wb - wc >= -tol;
}

// What a body's surface nodes span in a step: their box, their largest |v| and |a|.
struct BodyReach {
  Eigen::AlignedBox3d box;
  double v = 0.0, a = 0.0;
  void join(const BodyReach& other) {
    box.extend(other.box);
    v = std::max(v, other.v);
    a = std::max(a, other.a);
  }
};

// The bodies' reach joined over the ranks of a team: a maximum of (-min, max, v, a), exact.
void join_reach_over_ranks(const ReplicaTeam& team, std::vector<BodyReach>& bodies) {
  constexpr size_t kWidth = 8;
  std::vector<double> packed(kWidth * bodies.size());
  for (size_t b = 0; b < bodies.size(); ++b) {
    double* p = packed.data() + kWidth * b;
    for (int c = 0; c < 3; ++c) {
      p[c] = -bodies[b].box.min()[c];
      p[3 + c] = bodies[b].box.max()[c];
    }
    p[6] = bodies[b].v;
    p[7] = bodies[b].a;
  }
  team.max_over_ranks(packed);
  for (size_t b = 0; b < bodies.size(); ++b) {
    const double* p = packed.data() + kWidth * b;
    bodies[b].box.min() = -Vec3(p[0], p[1], p[2]);
    bodies[b].box.max() = Vec3(p[3], p[4], p[5]);
    bodies[b].v = p[6];
    bodies[b].a = p[7];
  }
}

// Per body, `visit(reach, node)` over the surface nodes: this rank's share of them in chunks
// (each chunk its own reach, no line shared with another's), joined, then joined over the ranks.
// Boxes and maxima are the same for any cut.
template <typename Visit>
std::vector<BodyReach> reach_per_body(const SurfaceFeatures& f, size_t n_bodies,
                                      const ChunkedLoops& loops, const ReplicaTeam* team,
                                      Visit visit) {
  const ItemShare share = share_of(team, f.nodes.size());
  const size_t n = share.end - share.begin;
  std::vector<std::vector<BodyReach>> part(static_cast<size_t>(loops.chunks(n)));
  loops.run(n, [&](size_t begin, size_t end, int chunk) {
    std::vector<BodyReach> bodies(n_bodies);
    for (size_t i = share.begin + begin; i < share.begin + end; ++i)
      visit(bodies[static_cast<size_t>(f.node_body[i])], static_cast<size_t>(f.nodes[i]));
    part[static_cast<size_t>(chunk)] = std::move(bodies);
  });
  std::vector<BodyReach> bodies(n_bodies);
  for (const std::vector<BodyReach>& p : part)
    for (size_t b = 0; b < p.size(); ++b) bodies[b].join(p[b]);
  if (team) join_reach_over_ranks(*team, bodies);
  return bodies;
}

// Two bodies whose contact-surface boxes are apart (the largest per-axis gap G > 0) cannot come
// nearer than G in a step shorter than tau with k (b_A(tau) + b_B(tau)) = G + closing (closing =
// step_fraction h_min), k = 2: over a step h the predictor moves a node by h v_a + h^2/2 a_a, so
// each body's surface stays inside its box at t_n grown by b(h) = h max|v| + h^2/2 max|a| (its
// nodes' maxima, `bodies`) on every axis. Returns the smallest tau over such pairs (infinity
// when no pair is apart). Once the boxes overlap the candidate pairs take over.
double approach_limit(const std::vector<BodyReach>& bodies, double closing) {
  double tau_min = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < bodies.size(); ++i)
    for (size_t j = i + 1; j < bodies.size(); ++j) {
      const BodyReach& A = bodies[i];
      const BodyReach& B = bodies[j];
      if (A.box.isEmpty() || B.box.isEmpty()) continue;
      const Eigen::Vector3d gaps = (A.box.min() - B.box.max()).cwiseMax(B.box.min() - A.box.max());
      const double G = gaps.maxCoeff();
      if (!(G > 0.0)) continue;
      const double s = G + closing;
      constexpr double kReachSafety = 2.0;  // as the rigid penalty's
      const double v = kReachSafety * (A.v + B.v), a = kReachSafety * (A.a + B.a);
      if (!(v > 0.0 || a > 0.0)) continue;
      // b(tau) = s: the root of a/2 tau^2 + v tau = s without cancellation.
      tau_min = std::min(tau_min, 2.0 * s / (v + std::sqrt(v * v + 2.0 * a * s)));
    }
  return tau_min;
}

// Two unit vectors completing the unit vector n to an orthonormal basis.
std::pair<Vec3, Vec3> tangent_basis(const Vec3& n) {
  const Vec3 helper = std::abs(n.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 t1 = n.cross(helper).normalized();
  return {t1, n.cross(t1)};
}

}  // namespace

DcrContact::DcrContact(const ModelMesh& mesh, DcrSettings settings,
                       const std::vector<int>& fixed_nodes)
    : ContactModel("dcr", kCorrectionPhases),
      settings_(std::move(settings)),
      features_(make_surface_features(mesh, settings_.surfaces)),
      loops_(settings_.threads),
      edge_orientation_(features_),
      restitution_(mesh, settings_.restitution, anchored_bodies(mesh, fixed_nodes)),
      projection_update_(mesh, features_.nodes),
      output_(mesh, contact_bodies(features_), settings_.output),
      anchored_(anchored_bodies(mesh, fixed_nodes)),
      held_(mesh.bodies.size()) {
  if (!kRestitutionRange.contains(settings_.restitution))
    throw std::invalid_argument("dcr: restitution " +
                                kRestitutionRange.problem(settings_.restitution));
  if (!kFrictionRange.contains(settings_.friction))
    throw std::invalid_argument("dcr: friction " + kFrictionRange.problem(settings_.friction));
  if (!(settings_.proximity > 0.0 && settings_.proximity <= 0.5))
    throw std::invalid_argument("dcr: proximity must lie in (0, 0.5] (fraction of an edge)");
  broad_phase_.use_loops(loops_);
  n_bodies_ = mesh.bodies.size();
  node_body_.assign(mesh.X.size(), -1);
  for (size_t b = 0; b < mesh.bodies.size(); ++b)
    for (int n = 0; n < mesh.bodies[b].n_nodes; ++n)
      node_body_[static_cast<size_t>(mesh.bodies[b].first_node + n)] = static_cast<int>(b);
  inv_m_.assign(mesh.X.size(), 0.0);  // filled from the state's masses at the first step
  for (int n : fixed_nodes) inv_m_[static_cast<size_t>(n)] = -1.0;  // marker: never moves
  X_ = mesh.X;
  lengths_ = reference_lengths(features_, X_);
  min_edge_ = lengths_.shortest;  // the shortest surface edge
  // Kept gap after projection: far below the mesh size, far above round-off.
  separation_ = 1e-4 * min_edge_;
  // Persistent contacts: far below an element, far above the kept separation.
  proximity_ = settings_.proximity * min_edge_;
  v_end_.assign(mesh.X.size(), Vec3::Zero());
  count_.assign(mesh.X.size(), 0);
  touched_.assign(mesh.X.size(), 0);
  distances_ = PairDistanceCache(mesh.X.size(), kReanchorFraction * min_edge_);
}

std::string DcrContact::failure() const {
  const double limit = kFailurePenetration * min_edge_;
  if (!(residual_ <= limit))  // also NaN
    return fmt::format(
        "residual penetration {:.4g} m exceeds {:.4g} m ({} x the shortest surface "
        "edge {:.4g} m) after {} iterations",
        residual_, limit, kFailurePenetration, min_edge_, settings_.max_projection_iterations);
  return {};
}

void DcrContact::begin_step(const State& state, double /*dt*/) {
  loops_.resolve_threads();
  if (x_n_.empty()) {  // first step: masses are known now
    for (size_t i = 0; i < inv_m_.size(); ++i)
      inv_m_[i] = inv_m_[i] < 0.0 ? 0.0 : 1.0 / state.m_lumped[i];
    x_n_.assign(state.x.size(), Vec3::Zero());
  }
  // The detection reads the start positions of the surface nodes only.
  for (int n : features_.nodes) x_n_[static_cast<size_t>(n)] = state.x[static_cast<size_t>(n)];
}

// g = sign * signed volume (docs/contact-method.md §1.1); returns it.
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
// broad phase is skipped (a scene pays for the search only while bodies are close). While the
// last step had candidate pairs the bodies are close, and the boxes are not formed: the search
// then runs, and finds nothing if they have just parted (the same result as skipping it; every
// rank of a team holds the same candidates, so all take the same branch).
bool DcrContact::bodies_may_touch(const State& s) const {
  if (settings_.self_contact) return true;
  if (!candidates_.node_face.empty() || !candidates_.edge_edge.empty()) return true;
  std::vector<BodyReach> bodies =
      reach_per_body(features_, n_bodies_, loops_, team_, [&](BodyReach& r, size_t node) {
        r.box.extend(x_n_[node]);
        r.box.extend(s.x[node]);
      });
  for (BodyReach& r : bodies)
    if (!r.box.isEmpty()) {
      r.box.min().array() -= proximity_;
      r.box.max().array() += proximity_;
    }
  for (size_t a = 0; a < bodies.size(); ++a)
    for (size_t b = a + 1; b < bodies.size(); ++b)
      if (!bodies[a].box.isEmpty() && !bodies[b].box.isEmpty() &&
          bodies[a].box.intersects(bodies[b].box))
        return true;
  return false;
}

void DcrContact::use_replica_team(ReplicaTeam& team) {
  team_ = &team;
  restitution_.use_replica_team(team);
  broad_phase_.use_team(team);
}

void DcrContact::detect(const State& s) {
  constraints_.clear();
  candidate_is_constraint_.clear();
  if (!bodies_may_touch(s)) {
    candidates_.node_face.clear();  // the step limit reads them
    candidates_.edge_edge.clear();
    return;
  }
  // Edge pairs are contacts only by a crossing: their boxes need no proximity, only the CCD's
  // inclusion allowance (kPrefilterSlack x the longest edge, ten times the CCD's 1e-6 parameter
  // tolerance of an edge at its reference length) and the broad phase's look-ahead of a step.
  const EdgeInflation edges{.floor = kPrefilterSlack * lengths_.longest};
  broad_phase_.find(features_, x_n_, s.x, proximity_, settings_.self_contact, candidates_, &edges);
  distances_.prepare(candidates_, features_.nodes, x_n_, s.x);
  candidate_is_constraint_.assign(candidates_.node_face.size() + candidates_.edge_edge.size(), 0);
  test_candidates(s, false);
}

// Tests the candidates that are no constraint yet (only_touched: only those with a node the
// projection moved) and appends the contacts among them to the constraints, in candidate order;
// returns how many. A candidate's test reads the positions only, so the candidates are shared
// among threads in chunks, and the chunks' contacts are joined in chunk order: the same list,
// in the same order, as one thread's.
int DcrContact::test_candidates(const State& s, bool only_touched) {
  const size_t n = candidate_is_constraint_.size();
  PairDistanceCache* cache = &distances_;
  found_.reset(loops_.chunks(n, ChunkedLoops::kHeavyItem));
  loops_.run(
      n,
      [&](size_t begin, size_t end, int chunk) {
        for (size_t k = begin; k < end; ++k) {
          if (candidate_is_constraint_[k] || (only_touched && !candidate_touched(k))) continue;
          if (const std::optional<Constraint> c = candidate_contact(s, k, cache)) {
            found_[chunk].push_back(*c);
            candidate_is_constraint_[k] = 1;  // one byte per candidate: no two chunks share one
          }
        }
      },
      ChunkedLoops::kHeavyItem);
  const size_t before = constraints_.size();
  found_.append_to(constraints_);
  return static_cast<int>(constraints_.size() - before);
}

// Candidate k (node-face pairs first, then edge-edge pairs) as a contact at the current
// positions, if it is one.
std::optional<Constraint> DcrContact::candidate_contact(const State& s, size_t k,
                                                        PairDistanceCache* cache) const {
  const size_t n_nf = candidates_.node_face.size();
  if (cache && cache->proves_apart_for_any_nodes(k, k < n_nf ? proximity_ : 0.0))
    return std::nullopt;
  if (k < n_nf) {
    const NodeFaceCandidate& nf = candidates_.node_face[k];
    return node_face_contact(s, features_.nodes[static_cast<size_t>(nf.node)],
                             features_.faces[static_cast<size_t>(nf.face)], k, cache);
  }
  const EdgeEdgeCandidate& ee = candidates_.edge_edge[k - n_nf];
  return edge_edge_contact(s, ee.edge_a, ee.edge_b, k, cache);
}

// Whether candidate k has a node that the projection moved (touched_).
bool DcrContact::candidate_touched(size_t k) const {
  auto touched = [&](int a, int b, int c, int d) {
    return touched_[static_cast<size_t>(a)] || touched_[static_cast<size_t>(b)] ||
           touched_[static_cast<size_t>(c)] || touched_[static_cast<size_t>(d)];
  };
  const size_t n_nf = candidates_.node_face.size();
  if (k < n_nf) {
    const NodeFaceCandidate& nf = candidates_.node_face[k];
    const Triangle& t = features_.faces[static_cast<size_t>(nf.face)];
    return touched(features_.nodes[static_cast<size_t>(nf.node)], t[0], t[1], t[2]);
  }
  const EdgeEdgeCandidate& ee = candidates_.edge_edge[k - n_nf];
  const auto& a = features_.edges[static_cast<size_t>(ee.edge_a)];
  const auto& b = features_.edges[static_cast<size_t>(ee.edge_b)];
  return touched(a[0], a[1], b[0], b[1]);
}

// The projection moves nodes after detection, so it can push a node through a face (or an edge
// through an edge) that was no contact before: every candidate with a node the projection moved
// is tested again on [x_n, x~]. Returns how many became constraints.
int DcrContact::redetect(const State& s) {
  bool any = false;
  for (size_t k = 0; k < moved_.size(); ++k)
    if (s.x[static_cast<size_t>(moved_[k])] != x_start_[k]) {
      touched_[static_cast<size_t>(moved_[k])] = 1;
      any = true;
    }
  if (!any) return 0;  // the projection moved nothing (a contact at rest): nothing new to test
  distances_.update_reach(moved_, x_n_, s.x);
  const int added = test_candidates(s, true);
  for (int n : moved_) touched_[static_cast<size_t>(n)] = 0;
  return added;
}

// A node and a face are a contact when the node, arriving from the outward side (g(x_n) >= 0),
// crosses the face during the step (CCD), or stays outward within the proximity distance of it
// with its projection inside the face (persistent contact). A pair that provably stays farther
// than the proximity distance from the face is neither (ccd_prefilter.hpp); the cache may prove
// it from an earlier step's distance (pair_distance_cache.hpp).
std::optional<Constraint> DcrContact::node_face_contact(const State& s, int p, const Triangle& t,
                                                        size_t k, PairDistanceCache* cache) const {
  const std::vector<Vec3>& x0 = x_n_;
  const std::vector<Vec3>& x1 = s.x;
  const std::array<int, 4> nodes{p, t[0], t[1], t[2]};
  if (cache && cache->proves_apart(k, nodes, 1, proximity_)) return std::nullopt;
  // A recorded pair the record cannot prove apart sits near the face (two touching surfaces).
  // It is decided without its distance where it can be: a node that starts inward is no
  // contact, a persistent one is (the prefilter below never rejects a persistent pair: it
  // rejects only a node farther than the proximity plus its slack, 2e-5 of the face's longest
  // edge at least, from the face over the whole step, and a persistent node is within the
  // proximity plus 2e-6 of that edge), and one that stays off the face's plane is none (no CCD
  // hit, ccd_prefilter.hpp). A pair without a record takes the distance first, so that the
  // record can decide it cheaply in the next steps.
  if (cache && cache->has_record(k)) {
    if (node_face_volume(x0[p], x0[t[0]], x0[t[1]], x0[t[2]]) < 0.0) return std::nullopt;
    if (persists_within_proximity(x1[p], x1[t[0]], x1[t[1]], x1[t[2]]))
      return Constraint{nodes, true, 1.0, false};
    if (node_stays_off_face_plane(x0[p], x0[t[0]], x0[t[1]], x0[t[2]], x1[p], x1[t[0]], x1[t[1]],
                                  x1[t[2]]))
      return std::nullopt;
  }
  const double d0 = point_triangle_distance(x0[p], x0[t[0]], x0[t[1]], x0[t[2]]);
  const double slack = face_slack(x0[t[0]], x0[t[1]], x0[t[2]]);
  if (cache) cache->record(k, nodes, 1, d0, slack);
  const double reach =
      node_face_reach(x0[p], x0[t[0]], x0[t[1]], x0[t[2]], x1[p], x1[t[0]], x1[t[1]], x1[t[2]]);
  if (!node_face_may_touch_within(d0, reach, slack, proximity_)) return std::nullopt;
  if (node_face_volume(x0[p], x0[t[0]], x0[t[1]], x0[t[2]]) < 0.0) return std::nullopt;
  // Either test makes the pair the same contact: the cheap persistent test goes first, so that a
  // resting pair (the common case of resting contact) needs no CCD. Without it, the pair is a
  // contact only if the CCD finds a crossing, which the prefilter without the proximity term
  // rules out for a node that stays farther from the face than its motion (ccd_prefilter.hpp).
  if (persists_within_proximity(x1[p], x1[t[0]], x1[t[1]], x1[t[2]]))
    return Constraint{nodes, true, 1.0, false};
  if (node_face_may_touch_within(d0, reach, slack, 0.0) &&
      node_face_ccd(x0[p], x0[t[0]], x0[t[1]], x0[t[2]], x1[p], x1[t[0]], x1[t[1]], x1[t[2]],
                    kInclusionTolerance)
          .has_value())
    return Constraint{nodes, true, 1.0, false};
  return std::nullopt;
}

// Persistent contact at the end positions: the node lies outward of the face within the
// proximity distance (0 <= g <= proximity x |face| / 3 for the volume measure g) and projects
// inside it.
bool DcrContact::persists_within_proximity(const Vec3& p, const Vec3& a, const Vec3& b,
                                           const Vec3& c) const {
  const double g1 = node_face_volume(p, a, b, c);
  const double third_area = (b - a).cross(c - a).norm() / 6.0;
  return g1 >= 0.0 && g1 <= proximity_ * third_area &&
         projects_inside(p, a, b, c, kPersistentTolerance);
}

// Two edges are a contact when they cross during the step (CCD); the admissible side is the one
// they started on (the thesis's orientation tag). Pairs that provably stay apart are decided by
// the prefilter (ccd_prefilter.hpp), or by the cache from an earlier step's distance.
std::optional<Constraint> DcrContact::edge_edge_contact(const State& s, int edge_a, int edge_b,
                                                        size_t k, PairDistanceCache* cache) const {
  const std::vector<Vec3>& x0 = x_n_;
  const std::vector<Vec3>& x1 = s.x;
  const auto& ea = features_.edges[static_cast<size_t>(edge_a)];
  const auto& eb = features_.edges[static_cast<size_t>(edge_b)];
  const std::array<int, 4> nodes{ea[0], ea[1], eb[0], eb[1]};
  if (cache && cache->proves_apart(k, nodes, 2, 0.0)) return std::nullopt;
  // A recorded pair the record cannot prove apart sits near the other edge (two touching
  // surfaces): if the edges stay off their common plane over the step they cannot cross, which
  // decides it without its distance (ccd_prefilter.hpp). A pair without a record takes the
  // distance first, so that the record can decide it cheaply in the next steps.
  if (cache && cache->has_record(k) &&
      edges_stay_off_plane(x0[ea[0]], x0[ea[1]], x0[eb[0]], x0[eb[1]], x1[ea[0]], x1[ea[1]],
                           x1[eb[0]], x1[eb[1]]))
    return std::nullopt;
  const double d0 = segment_distance(x0[ea[0]], x0[ea[1]], x0[eb[0]], x0[eb[1]]);
  if (cache)
    cache->record(k, nodes, 2, d0, edge_pair_slack(x0[ea[0]], x0[ea[1]], x0[eb[0]], x0[eb[1]]));
  if (!edges_may_cross_from(d0, x0[ea[0]], x0[ea[1]], x0[eb[0]], x0[eb[1]], x1[ea[0]], x1[ea[1]],
                            x1[eb[0]], x1[eb[1]]))
    return std::nullopt;
  if (!edge_edge_ccd(x0[ea[0]], x0[ea[1]], x0[eb[0]], x0[eb[1]], x1[ea[0]], x1[ea[1]], x1[eb[0]],
                     x1[eb[1]], kInclusionTolerance))
    return std::nullopt;
  // The side the edges start on; where they start in one plane, the side the surfaces face
  // (edge_orientation.hpp).
  const double sign = edge_orientation_.sign(features_, edge_a, edge_b, x0, separation_);
  return Constraint{nodes, false, sign, false};
}

// The order in which the solves visit the constraints: by a key from the reference positions
// of the constraint's features (node-face: the node, then the face's centroid; edge-edge: the
// two midpoints), so that it depends on the geometry only, never on the node numbering or on
// the order in which the search found the pairs (the thesis's DCR depended on both, 2.4.2).
void DcrContact::order_constraints() {
  // The same constraints as the last ordering, in the same list order (a contact at rest): the
  // same keys, so the same order.
  const bool same = ordered_.size() == constraints_.size() &&
                    std::equal(constraints_.begin(), constraints_.end(), ordered_.begin(),
                               [](const Constraint& c, const auto& o) {
                                 return c.nodes == o.first && c.node_face == o.second;
                               });
  if (same) return;
  ordered_.resize(constraints_.size());
  for (size_t k = 0; k < constraints_.size(); ++k)
    ordered_[k] = {constraints_[k].nodes, constraints_[k].node_face};
  keys_.resize(constraints_.size());
  for (size_t k = 0; k < constraints_.size(); ++k) {
    const Constraint& c = constraints_[k];
    auto X = [&](int j) { return X_[static_cast<size_t>(c.nodes[j])]; };
    ConstraintKey& key = keys_[k];
    if (c.node_face) {
      std::array<Vec3, 3> face{X(1), X(2), X(3)};  // summed in a canonical order
      std::sort(face.begin(), face.end(), [](const Vec3& p, const Vec3& q) {
        return std::tie(p.x(), p.y(), p.z()) < std::tie(q.x(), q.y(), q.z());
      });
      const Vec3 centroid = (face[0] + face[1] + face[2]) / 3.0;
      key = {X(0).x(), X(0).y(), X(0).z(), centroid.x(), centroid.y(), centroid.z(), 0.0};
    } else {
      const Vec3 ma = 0.5 * (X(0) + X(1)), mb = 0.5 * (X(2) + X(3));
      key = {ma.x(), ma.y(), ma.z(), mb.x(), mb.y(), mb.z(), 1.0};
    }
  }
  order_.resize(constraints_.size());
  for (size_t k = 0; k < order_.size(); ++k) order_[k] = static_cast<int>(k);
  std::sort(order_.begin(), order_.end(), [&](int a, int b) {
    return keys_[static_cast<size_t>(a)] < keys_[static_cast<size_t>(b)];
  });
}

double DcrContact::mobility(const Constraint& c, const std::array<Vec3, 4>& grad) const {
  double W = 0.0;  // W = grad g^T M^-1 grad g
  for (int a = 0; a < 4; ++a) W += grad[a].squaredNorm() * inv_m_[static_cast<size_t>(c.nodes[a])];
  return W;
}

// The positions before the projection of the nodes of constraints [first, end) not seen yet.
// A node already remembered (a constraint of an earlier round holds it, and the projection may
// have moved it since) keeps its first position: the energy of the step's projection is measured
// from where the step's prediction put the nodes (listing it again from its projected position
// lost that part of the projection's work in the booking, by an amount that depended on the
// rounding: the coarse Hertz test's energy balance read 0.8 % at -O3 and 5.0 % at -O1).
void DcrContact::remember_start(const State& s, size_t first) {
  for (int n : moved_) count_[static_cast<size_t>(n)] = 1;
  for (size_t k = first; k < constraints_.size(); ++k)
    for (int n : constraints_[k].nodes) {
      const auto i = static_cast<size_t>(n);
      if (count_[i] != 0) continue;
      count_[i] = 1;
      moved_.push_back(n);
      x_start_.push_back(s.x[i]);
    }
  for (int n : moved_) count_[static_cast<size_t>(n)] = 0;
}

// Mass-weighted projection onto g >= separation * k (docs/contact-method.md §1.2): Newton steps
// lambda = (target - g) / W along M^-1 grad g, one constraint after the other in the geometric
// order, forward then backward (symmetric Gauss-Seidel), until every constraint holds. Each
// step moves the four nodes by amounts whose mass-weighted sum and moment vanish, so linear
// and angular momentum are conserved exactly.
// Returns whether the sweeps met the tolerance before the cap.
bool DcrContact::project_positions(State& s) {
  order_constraints();
  Vec3 grad[4];
  for (int sweep = 0; sweep < settings_.max_projection_iterations; ++sweep) {
    double worst = 0.0;
    const bool forward = sweep % 2 == 0;
    for (size_t j = 0; j < order_.size(); ++j) {
      Constraint& c =
          constraints_[static_cast<size_t>(order_[forward ? j : order_.size() - 1 - j])];
      const double scale = constraint_gradient(c, s.x, grad);
      // A constraint within the dead band already meets the sweeps' tolerance: it is left where
      // it is (projecting it would move its nodes by less than the tolerance, and still cost the
      // re-detection and the update of the elements around them).
      const double gap = separation_ * scale - constraint_value(c, s.x);
      if (gap <= kDeadBand * separation_ * scale) continue;
      double W = 0.0;
      for (int a = 0; a < 4; ++a)
        W += grad[a].squaredNorm() * inv_m_[static_cast<size_t>(c.nodes[a])];
      if (!(W > 0.0)) continue;
      worst = std::max(worst, gap / scale);
      const double lambda = gap / W;
      for (int a = 0; a < 4; ++a) {
        const auto n = static_cast<size_t>(c.nodes[a]);
        s.x[n] += lambda * inv_m_[n] * grad[a];
      }
      c.projected = true;
    }
    if (worst <= kDeadBand * separation_) return true;
  }
  return constraints_.empty();
}

// Projection, re-detection of what it pushed through, projection again, ... (at most
// kDetectionRounds rounds); then the forces and stored energy of the elements around the moved
// nodes are brought to the new positions (projection_update.hpp). The residual is measured where
// the velocity rows are made from the same positions (exchange_momentum).
void DcrContact::enforce_positions(State& s, double dt) {
  moved_.clear();
  x_start_.clear();
  remember_start(s, 0);
  for (int round = 1;; ++round) {
    if (!project_positions(s)) ++unconverged_projection_;
    if (round == kDetectionRounds) break;
    const size_t first_new = constraints_.size();
    if (redetect(s) == 0) break;
    remember_start(s, first_new);
  }
  size_t kept = 0;  // the constraint nodes that actually moved
  for (size_t k = 0; k < moved_.size(); ++k)
    if (s.x[static_cast<size_t>(moved_[k])] != x_start_[k]) {
      moved_[kept] = moved_[k];
      x_start_[kept++] = x_start_[k];
    }
  moved_.resize(kept);
  x_start_.resize(kept);
  if (kept > 0) {
    ++projecting_steps_;
    // A partitioned run's view holds the surfaces; the elements' other nodes come now.
    if (team_) team_->make_nodes_current(projection_update_.element_nodes(moved_));
    const ProjectionUpdate::EnergyChange dE =
        projection_update_.apply(moved_, x_start_, s, inv_m_, dt);
    projection_stored_ = dE.stored;
    projected_stable_dt_ = dE.stable_dt;
    if (dE.jump_ratio > 0.0) projection_jump_dt_ = dt * std::sqrt(kProjectionJump / dE.jump_ratio);
    work_ += dE.total();
    parts_.projection += dE.total();
  }
}

void DcrContact::correct(State& s, double dt) {
  const bool report = output_.wants_anything();
  if (report) output_.begin(s);
  detect(s);
  last_impulse_ = projection_stored_ = 0.0;
  projected_stable_dt_ = projection_jump_dt_ = std::numeric_limits<double>::infinity();
  active_ = sweeps_ = 0;
  pair_impulses_.clear();
  near_.clear();
  rows_.clear();
  std::fill(held_.begin(), held_.end(), HeldImpulse{});
  residual_ = 0.0;  // measured by exchange_momentum
  if (!constraints_.empty()) {
    enforce_positions(s, dt);
    exchange_momentum(s, dt);
    collect_pair_impulses(s.x);
  }
  const double restitution_work = restitution_.after_solve(pair_impulses_, near_, s, dt);
  work_ += restitution_work;
  // The rigid bodies' share enters the check that the contact only dissipates, not the work.
  parts_.restitution += restitution_work + restitution_.last_rigid_energy();
  collect_held_impulses(s);
  if (report) {
    output_.add_impulses(rows_, restitution_.last_corrections(), node_body_);
    output_.finish(s, dt);
  }
}

// The velocity row of a contact (contact_impulses.hpp): the approach it may still make in the
// next step without closing the kept separation, its contact-point weights and tangents.
//
// Resting contact (docs/hard-scenes.md): the next step's predictor moves the nodes by
// dt (v_{n+1} + dt/2 a_{n+1}), so a contact whose acceleration presses it shut (grad g . a < 0:
// gravity, or the body behind it) and whose rate is held at -(g - g_sep)/dt would land below
// the kept separation by dt^2/2 |grad g . a| every step, to be projected back (and the elements
// around it re-evaluated). The target then also takes in that known acceleration and aims the
// next predicted position at kRestingAim x the separation:
//     rate_n >= -(g - kRestingAim g_sep)/dt - dt/2 grad g . a_{n+1}
// whenever that is the stricter bound. A resting node thus stays above the kept separation
// and the projection has nothing to do; the bound only ever asks for more separation (never
// less than the kept one), and an impulse still only pushes (lambda_n >= 0). It is applied only
// to resting contacts, where that push over one step, dt^2/2 |grad g . a| / k, is at most the
// separation: an impact is left as it was (applied to every pressed contact, the clapping fork
// of the [no_penetration] test left a node inside a foreign tet).
ContactRow DcrContact::make_row(const Constraint& c, const std::vector<Vec3>& x,
                                const std::vector<Vec3>& acc, double dt, double& distance) const {
  ContactRow r;
  r.nodes = c.nodes;
  const double scale = constraint_gradient(c, x, r.grad.data());
  const double g = constraint_value(c, x);
  distance = g / scale;
  r.target = -std::max(0.0, g - separation_ * scale) / dt;
  double pressing = 0.0;  // grad g . a
  for (int j = 0; j < 4; ++j) pressing += r.grad[j].dot(acc[static_cast<size_t>(c.nodes[j])]);
  // The next step dt' is as long as this one, except after a step shortened to land on an output
  // time: it is then about as long as the one before. The aim is taken over h = the longer of the
  // two: with rate = -(g - g_aim)/h - h/2 pressing, the next step changes g by
  //     dt' rate + dt'^2/2 pressing = -(dt'/h)(g - g_aim) + dt'/2 (dt' - h) pressing,
  // which for dt' <= h, pressing < 0 and g >= g_aim leaves g >= g_aim. Aimed over the short step,
  // the resting contacts landed about their push below the separation in the step after each
  // output time, to be projected there (and the elements around them evaluated again).
  const double h = std::max(dt, previous_dt_);
  if (pressing < 0.0 && -0.5 * h * h * pressing <= separation_ * scale)
    r.target =
        std::max(r.target, -(g - kRestingAim * separation_ * scale) / h - 0.5 * h * pressing);
  // All four gradients are parallel to the contact normal n at g = 0. The contact points are
  // sum beta_a x_a with beta_a = grad_a g . n / S, S normalising the first side's weights to 1
  // (node-face: the node; edge-edge: the first edge); the normal impulse is S lambda_n.
  int biggest = 0;
  for (int a = 1; a < 4; ++a)
    if (r.grad[a].squaredNorm() > r.grad[biggest].squaredNorm()) biggest = a;
  const Vec3 n = r.grad[biggest].normalized();
  for (int a = 0; a < (c.node_face ? 1 : 2); ++a) r.S += std::abs(r.grad[a].dot(n));
  if (!(r.S > 0.0) || !n.allFinite()) return r;  // W_n = 0: the row is inert
  r.W_n = mobility(c, r.grad);
  for (int a = 0; a < 4; ++a) {
    r.beta[a] = r.grad[a].dot(n) / r.S;
    r.W_t += r.beta[a] * r.beta[a] * inv_m_[static_cast<size_t>(c.nodes[a])];
  }
  std::tie(r.t1, r.t2) = tangent_basis(n);
  return r;
}

// Normal and friction impulses on the end-of-step velocity v_end = v* + dt/2 a_{n+1}, solved
// together (contact_impulses.hpp); the change is added to v* so the velocity correction lands on
// it, and its kinetic energy change is the contact's work.
void DcrContact::exchange_momentum(State& s, double dt) {
  std::vector<Vec3>& v_end = v_end_;  // only the constrained nodes are read or written
  v_before_.clear();
  near_.clear();
  rows_.clear();
  for (const Constraint& c : constraints_) {
    for (int n : c.nodes) {
      const auto i = static_cast<size_t>(n);
      v_end[i] = s.v[i] + 0.5 * dt * s.a[i];
      v_before_.push_back(v_end[i]);
    }
    double distance = 0.0;
    rows_.push_back(make_row(c, s.x, s.a, dt, distance));
    residual_ = std::max(residual_, -distance);  // at the positions the projection left
    const int a = body_of(c.nodes[0]), b = body_of(c.nodes[3]);
    if (a != b) near_.emplace_back(std::min(a, b), std::max(a, b));
  }
  std::sort(near_.begin(), near_.end());
  near_.erase(std::unique(near_.begin(), near_.end()), near_.end());
  restitution_.before_solve(near_, s, dt);
  partners_.reset(s, node_body_, n_bodies_);
  const double rigid_energy = partners_.kinetic_energy();
  const ImpulseSolve solve = impulses_.solve(rows_, order_, inv_m_, v_end,
                                             {.friction = settings_.friction,
                                              .max_iterations = settings_.max_iterations,
                                              .tolerance = kVelocityTolerance,
                                              .velocity_floor = kVelocityFloor * separation_ / dt},
                                             &partners_, &s.x);
  // The free rigid bodies' kinetic energy the impulses changed: the contact's work on them, for
  // the check that it only dissipates (the body takes the impulses at the end of the step).
  parts_.impulses += partners_.kinetic_energy() - rigid_energy;
  sweeps_ = solve.sweeps;
  if (!solve.converged) ++unconverged_velocity_;

  size_t k = 0;
  for (size_t j = 0; j < constraints_.size(); ++j) {
    last_impulse_ += rows_[j].lambda_n * rows_[j].S;
    if (constraints_[j].projected || rows_[j].lambda_n > 0.0) ++active_;
    for (int n : constraints_[j].nodes) {
      const auto i = static_cast<size_t>(n);
      const Vec3& before = v_before_[k++];
      if (count_[i] != 0) continue;  // a node shared by constraints is applied once
      count_[i] = 1;
      const double dK = 0.5 * s.m_lumped[i] * (v_end[i].squaredNorm() - before.squaredNorm());
      work_ += dK;
      parts_.impulses += dK;
      s.v[i] += v_end[i] - before;
    }
  }
  for (const Constraint& c : constraints_)
    for (int n : c.nodes) count_[static_cast<size_t>(n)] = 0;
}

// The impulse of every row on its held nodes (inv_m = 0), and of the restitution on anchored
// bodies, summed per body with their moments about the origin. A held node moving at v (a rigid
// body's) takes work J . v from the contact: it enters the check for injected energy beside the
// impulses' work on the free nodes (for a fixed node, v = 0).
void DcrContact::collect_held_impulses(const State& s) {
  for (size_t k = 0; k < rows_.size(); ++k) {
    const ContactRow& r = rows_[k];
    if (!(r.lambda_n > 0.0) && r.lambda_t1 == 0.0 && r.lambda_t2 == 0.0) continue;
    const Vec3 tangential = r.lambda_t1 * r.t1 + r.lambda_t2 * r.t2;
    for (int a = 0; a < 4; ++a) {
      const auto i = static_cast<size_t>(r.nodes[a]);
      if (inv_m_[i] != 0.0) continue;
      const Vec3 J = r.lambda_n * r.grad[a] + r.beta[a] * tangential;
      HeldImpulse& h = held_[static_cast<size_t>(node_body_[i])];
      h.impulse += J;
      h.moment += s.x[i].cross(J);
      // A free body's share is in its kinetic energy change (exchange_momentum).
      if (partners_.partner_of(r.nodes[a]) < 0) parts_.impulses += J.dot(s.v[i]);
    }
  }
  for (const PairImpulse& p : restitution_.last_corrections()) {
    if (anchored_[static_cast<size_t>(p.body_b)]) {
      held_[static_cast<size_t>(p.body_b)].impulse += p.impulse_on_b;
      held_[static_cast<size_t>(p.body_b)].moment += p.point.cross(p.impulse_on_b);
    }
    if (anchored_[static_cast<size_t>(p.body_a)]) {
      held_[static_cast<size_t>(p.body_a)].impulse -= p.impulse_on_b;
      held_[static_cast<size_t>(p.body_a)].moment -= p.point.cross(p.impulse_on_b);
    }
  }
}

void DcrContact::add_held_impulses(std::vector<HeldImpulse>& per_body) const {
  for (size_t b = 0; b < held_.size() && b < per_body.size(); ++b) {
    per_body[b].impulse += held_[b].impulse;
    per_body[b].moment += held_[b].moment;
  }
}

// This step's normal impulses between two bodies, for the restitution: the impulse on the body
// with the larger index, acting at the mean of the contact's four nodes.
void DcrContact::collect_pair_impulses(const std::vector<Vec3>& x) {
  for (size_t k = 0; k < constraints_.size(); ++k) {
    const Constraint& c = constraints_[k];
    const ContactRow& r = rows_[k];
    const int a = body_of(c.nodes[0]), b = body_of(c.nodes[3]);
    if (a == b || !(r.lambda_n > 0.0)) continue;
    PairImpulse p{std::min(a, b), std::max(a, b), Vec3::Zero(), Vec3::Zero()};
    for (int j = 0; j < 4; ++j) {
      if (body_of(c.nodes[j]) == p.body_b) p.impulse_on_b += r.lambda_n * r.grad[j];
      p.point += 0.25 * x[static_cast<size_t>(c.nodes[j])];
    }
    pair_impulses_.push_back(p);
  }
}

// The step bound (docs/contact-time-step.md, "DCR"), kinematic only: every candidate pair of the
// last broad phase may approach by at most its gap plus step_fraction of its own shortest edge
// in one step (step_limit.hpp), and two bodies whose surfaces are still apart may close at most
// their gap plus step_fraction of the shortest edge (approach_limit). The projection then stays
// a small correction, and the end-of-step configuration of a pair stays close to the linear
// path the CCD assumed.
ContactStepBound DcrContact::step_bound(const State& state, double ceiling) const {
  // The largest squared |v| and |a| first, their roots after: the same (the root is monotone and
  // correctly rounded, and norm() is the root of squaredNorm()), at one root per body.
  std::vector<BodyReach> bodies =
      reach_per_body(features_, n_bodies_, loops_, team_, [&](BodyReach& r, size_t node) {
        r.box.extend(state.x[node]);
        r.v = std::max(r.v, state.v[node].squaredNorm());
        r.a = std::max(r.a, state.a[node].squaredNorm());
      });
  double fastest = 0.0;
  for (BodyReach& r : bodies) {
    r.v = std::sqrt(r.v);
    r.a = std::sqrt(r.a);
    fastest = std::max(fastest, r.v);
  }
  const PairStepLimit local = pair_step_limit(features_, candidates_, lengths_, state.x, state.v,
                                              settings_.step_fraction, ceiling, fastest);
  // With self-contact the candidate pairs alone govern.
  const double apart = settings_.self_contact
                           ? std::numeric_limits<double>::infinity()
                           : approach_limit(bodies, settings_.step_fraction * min_edge_);
  return {.kinematic_dt = std::min({local.dt, apart, projection_jump_dt_})};
}

void DcrContact::end_step(const State& /*state*/, double dt) {
  previous_dt_ = dt;
  ledger_ = {.work = work(),
             .injected_energy = injected_energy(),
             .touching = active_ > 0,
             .failure = failure()};
}

std::vector<std::string> DcrContact::history_columns() const {
  const std::string& p = settings_.history_prefix;
  std::vector<std::string> c = {p + ".active", p + ".normal_impulse", p + ".work",
                                p + ".residual_penetration"};
  for (std::string& name : output_.columns()) c.push_back(std::move(name));
  return c;
}

void DcrContact::append_history(const State& /*s*/, std::vector<double>& row) const {
  row.insert(row.end(),
             {static_cast<double>(constraints_.size()), last_impulse_, work_, residual_});
  output_.append(row);
}

}  // namespace ccm::dcr
