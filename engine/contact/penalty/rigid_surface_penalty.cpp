#include "engine/contact/penalty/rigid_surface_penalty.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "engine/body/mass_properties.hpp"
#include "engine/contact/penalty/surface_quadrature.hpp"
#include "engine/core/parameter_ranges.hpp"

namespace ccm {
namespace {

// The rigid body's boundary as a closed surface with local vertex ids, and the global ids.
SurfaceDistance rigid_surface(const ModelMesh& mesh, int body, std::vector<Triangle>& global) {
  const Body& b = mesh.bodies.at(static_cast<size_t>(body));
  global = b.boundary;
  std::vector<Vec3> vertices(static_cast<size_t>(b.n_nodes));
  for (int n = 0; n < b.n_nodes; ++n)
    vertices[static_cast<size_t>(n)] = mesh.X[static_cast<size_t>(b.first_node + n)];
  std::vector<Triangle> local = b.boundary;
  for (Triangle& t : local)
    for (int& n : t) n -= b.first_node;
  return SurfaceDistance(std::move(vertices), std::move(local));
}

double checked_crease(double degrees) {
  if (!kCreaseAngleRange.contains(degrees))
    throw std::invalid_argument("penalty: the crease angle " + kCreaseAngleRange.problem(degrees));
  return degrees;
}

int local_index(const std::vector<int>& sorted, int global) {
  return static_cast<int>(std::lower_bound(sorted.begin(), sorted.end(), global) - sorted.begin());
}

}  // namespace

RigidSurfacePenalty::RigidSurfacePenalty(const ModelMesh& mesh, std::vector<Triangle> surface,
                                         int rigid_body, RigidSurfacePenaltyParams params)
    : ContactModel("rigid_surface_penalty", kForcePhases),
      params_(std::move(params)),
      rigid_body_(rigid_body),
      tris_(std::move(surface)),
      distance_(rigid_surface(mesh, rigid_body, rigid_tris_)),
      smooth_(distance_.vertices(), distance_.triangles(), checked_crease(params_.crease_angle)) {
  if (!smooth_.all_flat()) distance_.set_allowance(smooth_.allowances());
  reach_ = distance_.largest_allowance();
  if (tris_.empty()) throw std::invalid_argument("penalty: the deformable surface is empty");
  if (!mesh.bodies.at(static_cast<size_t>(rigid_body)).rigid)
    throw std::invalid_argument(
        "penalty: body '" + mesh.bodies[static_cast<size_t>(rigid_body)].name + "' is not rigid");
  if (!(params_.penalty > 0.0) || !std::isfinite(params_.penalty))
    throw std::invalid_argument("penalty: K_P must be > 0");
  if (!kDampingRange.contains(params_.damping))
    throw std::invalid_argument("penalty: the damping " + kDampingRange.problem(params_.damping));
  damping_factor_ = std::sqrt(1.0 + params_.damping * params_.damping) - params_.damping;
  for (const auto* list : {&tris_, &rigid_tris_})
    for (const Triangle& t : *list) nodes_.insert(nodes_.end(), t.begin(), t.end());
  std::sort(nodes_.begin(), nodes_.end());
  nodes_.erase(std::unique(nodes_.begin(), nodes_.end()), nodes_.end());
  rigid_node_.assign(nodes_.size(), 0);
  rigid_touched_.assign(nodes_.size(), 0);
  triangles_at_.assign(nodes_.size(), 0.0);
  for (const Triangle& t : tris_)
    for (int n : t) {
      tri_local_.push_back(local_index(nodes_, n));
      triangles_at_[static_cast<size_t>(tri_local_.back())] += 1.0;
    }
  for (const Triangle& t : rigid_tris_)
    for (int n : t) {
      rigid_local_.push_back(local_index(nodes_, n));
      rigid_node_[static_cast<size_t>(rigid_local_.back())] = 1;
    }
  hint_.assign(3 * tris_.size(), -1);
  lens_hint_.assign(3 * tris_.size(), -1);
  clear_.assign(3 * tris_.size(), Clearance{});
  foot_.assign(3 * tris_.size(), Foot{});
  evaluated_.assign(3 * tris_.size(), Evaluated{});
  for (size_t i = 0; i < nodes_.size(); ++i)
    if (!rigid_node_[i]) deformable_local_.push_back(static_cast<int>(i));
  f_now_.assign(nodes_.size(), Vec3::Zero());
  f_prev_ = f_now_;
  x_prev_ = f_now_;
  outcode_.assign(nodes_.size(), 0);
  x_ref_.assign(nodes_.size(), Vec3::Zero());
  // The bounding sphere about the body's centre of mass (its rotation leaves it unchanged).
  const Body& rb = mesh.bodies[static_cast<size_t>(rigid_body)];
  const std::vector<Tet> tets(mesh.tets.begin() + rb.first_element,
                              mesh.tets.begin() + rb.first_element + rb.n_elements);
  const Vec3 c0 = tet_mass_properties(tets, mesh.X, 1.0).center;
  for (int n = rb.first_node; n < rb.first_node + rb.n_nodes; ++n)
    bound2_ = std::max(bound2_, (mesh.X[static_cast<size_t>(n)] - c0).squaredNorm());
  bound2_ = std::pow(std::sqrt(bound2_) + reach_, 2);
}

const RigidState* RigidSurfacePenalty::pose(const State& s) const {
  for (const RigidState& r : s.rigid)
    if (r.body == rigid_body_) return &r;
  return nullptr;
}

// x in the body's frame: X = c_0 + R^T (x - c). to_reference() rotates by the quaternion, as
// the contact's points always have (their results depend on it to the last bit);
// to_reference_fast() by R^T as a matrix, formed once per pose, for the candidate filter.
RigidSurfacePenalty::Frame::Frame(const RigidState& r)
    : pose(r), back(r.rotation.conjugate().toRotationMatrix()) {}

Vec3 RigidSurfacePenalty::Frame::to_reference(const Vec3& x) const {
  return pose.reference_center + pose.rotation.conjugate() * (x - pose.center);
}

Vec3 RigidSurfacePenalty::Frame::to_reference_fast(const Vec3& x) const {
  return pose.reference_center + back * (x - pose.center);
}

// Only the deformable nodes and the rigid nodes that took a force (rigid_now_) carry a force:
// the other entries of f_now_ and f_prev_ stay zero, and no step reads or writes them.
void RigidSurfacePenalty::begin_step(const State& s, double /*dt*/) {
  for (int i : deformable_local_)
    x_prev_[static_cast<size_t>(i)] = s.x[static_cast<size_t>(nodes_[static_cast<size_t>(i)])];
  for (int i : rigid_prev_) f_prev_[static_cast<size_t>(i)].setZero();
  for (int i : deformable_local_) f_prev_[static_cast<size_t>(i)] = f_now_[static_cast<size_t>(i)];
  for (int i : rigid_now_) f_prev_[static_cast<size_t>(i)] = f_now_[static_cast<size_t>(i)];
  rigid_prev_ = rigid_now_;
  const RigidState* r = pose(s);
  has_pose_prev_ = r != nullptr;
  if (r) {
    center_prev_ = r->center;
    rotation_prev_ = r->rotation;
  }
}

// Hands -f to the rigid triangle's nodes at the closest point's weights, noting the nodes.
void RigidSurfacePenalty::load_rigid(int triangle, const std::array<double, 3>& weights,
                                     const Vec3& f) {
  for (int a = 0; a < 3; ++a) {
    const auto i = static_cast<size_t>(
        rigid_local_[3 * static_cast<size_t>(triangle) + static_cast<size_t>(a)]);
    if (!rigid_touched_[i]) {
      rigid_touched_[i] = 1;
      rigid_now_.push_back(static_cast<int>(i));
    }
    f_now_[i] -= weights[static_cast<size_t>(a)] * f;
  }
}

// The deformable triangles that can hold a point within `margin` of the rigid surface: those
// whose nodes' box, in the body's frame, meets the surface's box grown by `margin` (a point of a
// triangle lies in its nodes' box). Each node's outcode marks the faces of the grown box it lies
// beyond (Cohen-Sutherland); the nodes' box misses the grown box when all three nodes lie beyond
// one face. Ascending, as the full loop would visit them.
const std::vector<int>& RigidSurfacePenalty::candidates(const State& s, const Frame& frame,
                                                        double margin) {
  const Vec3 lo = distance_.box()[0] - Vec3::Constant(margin);
  const Vec3 hi = distance_.box()[1] + Vec3::Constant(margin);
  for (int i : deformable_local_) {
    const Vec3 x =
        frame.to_reference_fast(s.x[static_cast<size_t>(nodes_[static_cast<size_t>(i)])]);
    x_ref_[static_cast<size_t>(i)] = x;
    unsigned code = 0;
    for (int d = 0; d < 3; ++d)
      code |= (x[d] < lo[d] ? 1u : 0u) << (2 * d) | (x[d] > hi[d] ? 2u : 0u) << (2 * d);
    outcode_[static_cast<size_t>(i)] = static_cast<unsigned char>(code);
  }
  candidates_.clear();
  for (size_t t = 0; t < tris_.size(); ++t)
    if ((outcode_[static_cast<size_t>(tri_local_[3 * t])] &
         outcode_[static_cast<size_t>(tri_local_[3 * t + 1])] &
         outcode_[static_cast<size_t>(tri_local_[3 * t + 2])]) == 0)
      candidates_.push_back(static_cast<int>(t));
  return candidates_;
}

// The margin that covers rounding between a point's frame change and its nodes' (relative
// 1e-9 of the body's size; a point that near the box is outside by far more than its depth).
double RigidSurfacePenalty::rounding_margin() const {
  return 1e-9 * (distance_.box()[1] - distance_.box()[0]).norm();
}

// PS.1 at every quadrature point of the deformable surface (those of candidate triangles: the
// others are outside the body). Each point's gap bound goes to near_ for the step bound that
// follows (record_near).
void RigidSurfacePenalty::add_forces(State& s) {
  const RigidState* r = pose(s);
  if (!r) throw std::logic_error("penalty: the rigid body has no state in this run");
  free_body_ = r->mobile();  // free or pinned: the work on it is in the energy balance
  for (int i : deformable_local_) f_now_[static_cast<size_t>(i)].setZero();
  for (int i : rigid_now_) {
    f_now_[static_cast<size_t>(i)].setZero();
    rigid_touched_[static_cast<size_t>(i)] = 0;
  }
  rigid_now_.clear();
  n_active_ = 0;
  near_.clear();
  near_of_ = {&s, s.t, near_margin_};
  const double radius = std::sqrt(bound2_);
  const Frame frame(*r);
  for (int candidate : candidates(s, frame, reach_ + near_margin_ + rounding_margin())) {
    const auto t = static_cast<size_t>(candidate);
    const Triangle& T = tris_[t];
    for (int k = 0; k < 3; ++k) {
      const size_t point = 3 * t + static_cast<size_t>(k);
      const auto N = surface_point_weights(k);
      Vec3 x = Vec3::Zero();
      for (int a = 0; a < 3; ++a)
        x += N[static_cast<size_t>(a)] * s.x[static_cast<size_t>(T[static_cast<size_t>(a)])];
      // Beyond the body's bounding sphere a point is outside: no query.
      const double d2 = (x - r->center).squaredNorm();
      if (d2 > bound2_) {
        const double outside = std::sqrt(d2) - radius;
        if (outside <= near_margin_) near_.push_back({outside, point, true});
        continue;
      }
      const Vec3 X = frame.to_reference(x);
      SurfacePoint hit;
      if (locate(point, X, hit)) {
        spring(s, *r, t, k, x, hit);
        near_.push_back({-hit.depth, point, false});
      } else {
        record_near(point, X, std::sqrt(d2));
      }
    }
  }
  for (const auto* list : {&deformable_local_, &rigid_now_})
    for (int i : *list)
      s.f[static_cast<size_t>(nodes_[static_cast<size_t>(i)])] += f_now_[static_cast<size_t>(i)];
}

// Whether point `point` (X in the body's frame) is inside the surface, with its depth, normal and
// reaction point in `hit` (NG.3); else its clearance and evaluation are kept (CL.1, CL.2).
bool RigidSurfacePenalty::locate(size_t point, const Vec3& X, SurfacePoint& hit) {
  if ((X - clear_[point].at).squaredNorm() < clear_[point].radius * clear_[point].radius)
    return false;  // CL.1
  if (!tracked(point, X, hit)) {
    SurfacePoint flat;
    flat.depth = 0.0;
    const SurfaceDistance::Side side =
        distance_.query(X, flat, &hint_[point], reach_ > 0.0, &lens_hint_[point]);
    if (side == SurfaceDistance::Side::outside) {
      remember_clearance(point, X, flat);
      // Minus its clearance: its distance itself on flat facets, a lens bound (LC.1) on curved.
      if (flat.depth < 0.0) evaluated_[point] = {X, flat.depth, true, reach_ == 0.0};
      // Tracked from its nearest curved facet's centre from now on: the patch there cannot
      // reach it while its clearance lasts, and shows its approach after.
      const bool curved = flat.depth < 0.0 && !smooth_.flat(flat.triangle);
      foot_[point] = {curved ? flat.triangle : -1, {1.0 / 3.0, 1.0 / 3.0}};
      return false;
    }
    if (side == SurfaceDistance::Side::deep) {
      clear_[point].radius = 0.0;
      evaluated_[point] = {X, flat.depth, true, true};
      if (failure_.empty())
        failure_ = fmt::format(
            "a point of the deformable surface is deeper than {:.3g} m inside the rigid body "
            "(the penalty K_P is too soft for this impact)",
            distance_.deep_depth());
      return false;
    }
    smooth_.evaluate(X, flat, hit, &foot_[point].weights);  // NG.3
    foot_[point].triangle = hit.triangle;
  }
  clear_[point].radius = 0.0;
  evaluated_[point] = {X, hit.depth, true, true};
  if (hit.depth > 0.0) return true;
  // Below a lift but above its patch: half its height above the patch as its clearance (CL.2:
  // NG.3's depth is the distance to the patch to first order).
  clear_[point] = {X, std::max(-0.5 * hit.depth - rounding_margin(), 0.0)};
  return false;
}

// PS.1 at point k of deformable triangle t (x in the world), inside by hit.depth: the spring and
// dashpot's force on the triangle's nodes and its opposite on the rigid body.
void RigidSurfacePenalty::spring(const State& s, const RigidState& r, size_t t, int k,
                                 const Vec3& x, const SurfacePoint& hit) {
  ++n_active_;
  penetration_max_ = std::max(penetration_max_, hit.depth);
  const auto N = surface_point_weights(k);
  const Triangle& T = tris_[t];
  Vec3 v = Vec3::Zero();
  double m = 0.0;
  for (int a = 0; a < 3; ++a) {
    const auto i = static_cast<size_t>(T[static_cast<size_t>(a)]);
    v += N[static_cast<size_t>(a)] * s.v[i];
    m += N[static_cast<size_t>(a)] * s.m_lumped[i] /
         triangles_at_[static_cast<size_t>(tri_local_[3 * t + static_cast<size_t>(a)])];
  }
  const double K = params_.penalty;
  const Vec3 n = r.rotation * hit.normal;
  const double u_n = n.dot(v - (r.velocity + r.angular_velocity.cross(x - r.center)));
  const double c = 2.0 * params_.damping * std::sqrt(K * m);
  const Vec3 f = std::max(0.0, K * hit.depth - c * u_n) * n;
  for (int a = 0; a < 3; ++a)
    f_now_[static_cast<size_t>(tri_local_[3 * t + static_cast<size_t>(a)])] +=
        N[static_cast<size_t>(a)] * f;
  load_rigid(hit.triangle, hit.weights, f);
}

// A point found outside (X in the body's frame, from_center from the body's centre): its cheap gap
// bound goes to near_ when it is within near_margin_.
void RigidSurfacePenalty::record_near(size_t point, const Vec3& X, double from_center) {
  Gap g{0.0, point, false};
  g.gap = gap_bound(point, X, from_center, near_margin_, g.loose);
  if (g.gap <= near_margin_) near_.push_back(g);
}

void RigidSurfacePenalty::end_step(const State& s, double /*dt*/) {
  auto add = [&](int local, const Vec3& x, const Vec3& x_prev) {
    const auto i = static_cast<size_t>(local);
    work_ += 0.5 * (f_prev_[i] + f_now_[i]).dot(x - x_prev);
  };
  for (int i : deformable_local_) {
    const auto n = static_cast<size_t>(nodes_[static_cast<size_t>(i)]);
    add(i, s.x[n], x_prev_[static_cast<size_t>(i)]);
  }
  // A kinematic body's share is its driver's. The nodes that took a force now, then those that
  // took one at the step's start only (both lists in the order the points first loaded them).
  const RigidState* r = pose(s);
  if (free_body_ && r && has_pose_prev_) {
    // A rigid node's place at the step's start follows from its place now and the two poses:
    // x_prev = c_prev + R_prev R^T (x - c).
    const Mat3 back =
        rotation_prev_.toRotationMatrix() * r->rotation.conjugate().toRotationMatrix();
    auto add_rigid = [&](int i) {
      const Vec3& x = s.x[static_cast<size_t>(nodes_[static_cast<size_t>(i)])];
      add(i, x, center_prev_ + back * (x - r->center));
    };
    for (int i : rigid_now_) add_rigid(i);
    for (int i : rigid_prev_)
      if (!rigid_touched_[static_cast<size_t>(i)]) add_rigid(i);
  }
  ledger_ = {.work = work_, .injected_energy = 0.0, .touching = n_active_ > 0, .failure = failure_};
}

// A point evaluated the step before on the curved surface: its foot there, tracked across the
// patches (NG.5) instead of a search (the same foot where it is unique; a search when the foot
// leaves the curved patches or the point is deeper than a search would accept).
bool RigidSurfacePenalty::tracked(size_t point, const Vec3& X, SurfacePoint& hit) {
  Foot& f = foot_[point];
  if (reach_ == 0.0 || f.triangle < 0) return false;
  std::array<double, 2> weights{};
  if (!smooth_.track(X, f.triangle, f.weights, hit, weights) ||
      !(hit.depth <= distance_.deep_depth())) {
    f.triangle = -1;
    return false;
  }
  f = {hit.triangle, weights};
  return true;
}

// CL.2 (add_forces): a point evaluated above a patch by h keeps h / 2 as its clearance.
// CL.1: a point found outside with clearance g (LC.1, surface_distance.hpp: no point of the
// surface or of its allowances nearer) stays outside while it moves by less than g in the body's
// frame. Outside decided by cells alone is remembered with lifts only (one cell). The radius keeps
// a margin for the rounding between the two frame maps (Frame).
void RigidSurfacePenalty::remember_clearance(size_t point, const Vec3& X,
                                             const SurfacePoint& outside) {
  // Decided by cells alone: with lifts, a clearance above one cell (SurfaceDistance::query).
  const double clearance =
      outside.depth < 0.0 ? -outside.depth : (reach_ > 0.0 ? distance_.cell_size() : 0.0);
  clear_[point] = {X, std::max(clearance - rounding_margin(), 0.0)};
}

// A lower bound of how far point `point` (x, body frame) lies outside the surface, <= 0 inside
// it, the cheap way: from its last evaluation (the body has moved since by a step: the depth is
// 1-Lipschitz to first order, held to a tenth of a cell) or its clearance (CL.1, CL.2, also
// 1-Lipschitz) or, outside the body's bounding sphere, its distance `from_center` (of the body's
// centre) less the sphere's radius. `loose`: the bound is one of these, not the gap itself, and
// sharp_gap() can raise it. Without any, sharp_gap().
double RigidSurfacePenalty::gap_bound(size_t point, const Vec3& x, double from_center,
                                      double beyond, bool& loose) const {
  const Evaluated& e = evaluated_[point];
  if (e.valid) {
    const double moved = (x - e.at).norm();
    if (moved <= 0.1 * distance_.cell_size()) {
      // (Outside and moved by half its gap since: look again.)
      loose = !e.exact || (e.depth < 0.0 && moved > -0.5 * e.depth);
      return -e.depth - moved - rounding_margin();
    }
  }
  const Clearance& c = clear_[point];
  const double remaining = c.radius - (x - c.at).norm();
  if (c.radius > 0.0 && remaining >= 0.0) {
    loose = true;
    return remaining;
  }
  // Outside the body's bounding sphere (about its centre of mass, the lifts within): by the
  // distance to it.
  const double outside = from_center - std::sqrt(bound2_);
  loose = outside > 0.0;
  bool exact = false;
  return loose ? outside : sharp_gap(point, x, beyond, exact);
}

// How far point `point` (x, body frame) lies outside the surface, <= 0 inside it: by its tracked
// foot when it has one (NG.5), else infinity when its cells show it farther than `beyond` (DS.2),
// else by a query (exact on flat facets; on curved ones NG.3 near the surface and the lens bound
// LC.1 beyond the lifts). `exact`: the gap itself (NG.3 to first order), not a lower bound.
double RigidSurfacePenalty::sharp_gap(size_t point, const Vec3& x, double beyond,
                                      bool& exact) const {
  exact = true;
  const Foot& f = foot_[point];
  if (reach_ > 0.0 && f.triangle >= 0) {
    SurfacePoint hit;
    std::array<double, 2> weights{};
    if (smooth_.track(x, f.triangle, f.weights, hit, weights)) return -hit.depth;
  }
  if (!distance_.inside_or_within(x, beyond)) return std::numeric_limits<double>::infinity();
  SurfacePoint flat, hit;
  flat.depth = 0.0;
  int hint = hint_[point], lens_hint = lens_hint_[point];
  const auto side = distance_.query(x, flat, &hint, reach_ > 0.0, &lens_hint);
  if (side == SurfaceDistance::Side::outside) {  // cells alone: a clearance above one cell
    exact = flat.depth < 0.0 && reach_ == 0.0;
    return flat.depth < 0.0 ? -flat.depth : (reach_ > 0.0 ? distance_.cell_size() : 0.0);
  }
  smooth_.evaluate(x, flat, hit);
  return -hit.depth;
}

// Point `point`'s place in the body's frame from its nodes' (candidates() filled them; the map is
// affine).
Vec3 RigidSurfacePenalty::reference_point(size_t point) const {
  const size_t t = point / 3;
  const auto N = surface_point_weights(static_cast<int>(point % 3));
  Vec3 x = Vec3::Zero();
  for (int a = 0; a < 3; ++a)
    x += N[static_cast<size_t>(a)] *
         x_ref_[static_cast<size_t>(tri_local_[3 * t + static_cast<size_t>(a)])];
  return x;
}

// The springs that act within the step load their nodes (kappa_a / m_a) and the body (n K_P / m):
// omega^2 from the points inside the surface first; then those that can reach it within the step
// that limit allows (twice the fastest approach times it) join, which can only shorten it. Each
// point's gap starts as its cheap bound (gap_bound); a loose one is looked at closely
// (sharp_gap) only when the point would otherwise join.
ContactStepBound RigidSurfacePenalty::step_bound(const State& s, double ceiling) const {
  const RigidState* r = pose(s);
  if (!r) return {};
  // The body's bounding sphere about its centre, and the fastest approach a point can make.
  double v_max = 0.0;
  const double reach = std::sqrt(bound2_);
  for (int i : deformable_local_)
    v_max = std::max(v_max, s.v[static_cast<size_t>(nodes_[static_cast<size_t>(i)])].norm());
  const double v_rel = v_max + r->velocity.norm() + r->angular_velocity.norm() * reach;
  const double travel = 2.0 * v_rel * std::min(ceiling, 1e300);  // safety factor 2
  const double K = params_.penalty;
  double omega2 = 0.0;
  int near = 0;
  auto add = [&](size_t point) {
    ++near;
    const size_t t = point / 3;
    for (int a = 0; a < 3; ++a) {
      const auto local = static_cast<size_t>(tri_local_[3 * t + static_cast<size_t>(a)]);
      const double m = s.m_lumped[static_cast<size_t>(nodes_[local])];
      if (m > 0.0) omega2 = std::max(omega2, K * triangles_at_[local] / m);
    }
  };
  // A pinned body answers by turning: its springs at up to `lever` from the axis load 1/J r^2.
  const double turning =
      r->inverse_mass == 0.0 && r->mobile() ? pin_lever(s, *r) * r->inverse_inertia.norm() : 0.0;
  auto limit = [&] {
    const double w2 = omega2 + K * near * (r->inverse_mass + turning);
    return 2.0 / std::sqrt(w2) * damping_factor_;
  };
  auto& self = const_cast<RigidSurfacePenalty&>(*this);  // the candidates and gaps are scratch
  // The points add_forces() recorded at this state, when they are all that can join: every other
  // point lies farther than the margin they were recorded to. Else all, afresh.
  const bool recorded = near_of_.state == &s && near_of_.t == s.t;
  const auto& inside = recorded ? self.sort_near(travel) : self.gather_gaps(s, *r, travel);
  for (size_t point : inside) add(point);
  // Then the others in the order they can arrive (tau = gap / 2 v_rel, the safety factor 2), each
  // while it can arrive within the step the springs so far allow; one that would cut the step
  // below its own arrival ends the step there instead (the sphere's rule,
  // rigid_sphere_penalty.cpp). A loose gap first goes back with its sharp value.
  const double infinite = std::numeric_limits<double>::infinity();
  double L = near > 0 ? limit() : infinite, kinematic = infinite;
  // The approaching points from a min-heap of their gaps (most never leave it).
  // (Only those that can arrive within the step the points inside allow: it only falls.)
  auto& heap = self.gaps_;
  double horizon = 2.0 * v_rel * L;
  // The next add_forces() records to twice what this step needs.
  self.near_margin_ = std::min(travel, 2.0 * horizon);
  if (recorded && near_of_.margin < std::min(travel, horizon)) {
    near = 0;  // the recorded points are not all that can join: all, afresh
    omega2 = 0.0;
    for (size_t point : self.gather_gaps(s, *r, travel)) add(point);
    L = near > 0 ? limit() : infinite;
    horizon = 2.0 * v_rel * L;
  }
  heap.erase(
      std::remove_if(heap.begin(), heap.end(), [&](const Gap& g) { return !(g.gap < horizon); }),
      heap.end());
  const auto farther = [](const Gap& a, const Gap& b) {
    return a.gap > b.gap || (a.gap == b.gap && a.point > b.point);
  };
  std::make_heap(heap.begin(), heap.end(), farther);
  while (!heap.empty()) {
    const double tau = v_rel > 0.0 ? heap.front().gap / (2.0 * v_rel) : infinite;
    if (tau >= L) break;
    std::pop_heap(heap.begin(), heap.end(), farther);
    Gap g = heap.back();
    heap.pop_back();
    if (g.loose) {
      self.sharpen(g, travel);
      if (g.gap > 0.0 && g.gap <= travel) {
        heap.push_back(g);
        std::push_heap(heap.begin(), heap.end(), farther);
      } else if (g.gap <= 0.0) {
        add(g.point);  // inside after all: it counts, as those above
        L = limit();
      }
      continue;
    }
    const int before = near;
    const double omega2_before = omega2;
    add(g.point);
    const double L_with = limit();
    if (L_with <= tau) {  // the step ends before this point can arrive
      near = before;
      omega2 = omega2_before;
      kinematic = tau;
      break;
    }
    L = L_with;
  }
  ContactStepBound b;
  if (near > 0) b.stiffness_dt = L;
  if (v_rel > 0.0) b.kinematic_dt = std::min(kinematic, 0.5 * distance_.deep_depth() / v_rel);
  if (near == 0 && !std::isfinite(kinematic)) return {};
  return b;
}

// The step bound's points (x in the body's frame) within the body's bounding sphere grown by
// `travel`: those inside the surface are returned (the scratch inside_), those outside by no more
// than `travel` go to gaps_ with their cheap bounds (gap_bound). A loose bound at or below zero is
// sharpened at once.
const std::vector<size_t>& RigidSurfacePenalty::gather_gaps(const State& s, const RigidState& r,
                                                            double travel) {
  inside_.clear();
  gaps_.clear();
  const double band = std::sqrt(bound2_) + travel;  // (the sphere holds the curved reach_)
  const Frame frame(r);
  for (int candidate : candidates(s, frame, travel + reach_ + rounding_margin()))
    for (size_t point = 3 * static_cast<size_t>(candidate), k = 0; k < 3; ++k, ++point) {
      const Vec3 x = reference_point(point);
      const double from_center = (x - r.reference_center).norm();
      if (from_center > band) continue;
      Gap g{0.0, point, false};
      g.gap = gap_bound(point, x, from_center, travel, g.loose);
      if (g.loose && g.gap <= 0.0) sharpen(g, travel);
      if (g.gap <= 0.0)
        inside_.push_back(point);
      else if (g.gap <= travel)
        gaps_.push_back(g);
    }
  return inside_;
}

// The points add_forces() recorded (near_): those inside are returned (the scratch inside_), those
// outside by no more than `travel` go to gaps_. A loose bound at or below zero is sharpened at
// once.
const std::vector<size_t>& RigidSurfacePenalty::sort_near(double travel) {
  inside_.clear();
  gaps_.clear();
  for (Gap g : near_) {
    if (g.loose && g.gap <= 0.0) sharpen(g, travel);
    if (g.gap <= 0.0)
      inside_.push_back(g.point);
    else if (g.gap <= travel)
      gaps_.push_back(g);
  }
  return inside_;
}

// A loose gap's sharp value (sharp_gap), kept as the point's evaluation: gap_bound() reads it
// while the point stays within a tenth of a cell, so the next steps need not look again.
void RigidSurfacePenalty::sharpen(Gap& g, double travel) {
  const Vec3 x = reference_point(g.point);
  bool exact = false;
  const double sharp = sharp_gap(g.point, x, travel, exact);
  if (std::isfinite(sharp)) evaluated_[g.point] = {x, -sharp, true, exact};
  g.gap = std::max(g.gap, sharp);
  g.loose = false;
}

// The farthest rigid node from a pinned body's axis point, squared [m^2].
double RigidSurfacePenalty::pin_lever(const State& s, const RigidState& r) const {
  double lever = 0.0;
  for (size_t i = 0; i < nodes_.size(); ++i)
    if (rigid_node_[i])
      lever = std::max(lever, (s.x[static_cast<size_t>(nodes_[i])] - r.pivot).squaredNorm());
  return lever;
}

std::vector<std::string> RigidSurfacePenalty::history_columns() const {
  return {params_.name + ".active_points", params_.name + ".penetration_max",
          params_.name + ".work",          params_.name + ".rigid_force_x",
          params_.name + ".rigid_force_y", params_.name + ".rigid_force_z"};
}

void RigidSurfacePenalty::append_history(const State& /*s*/, std::vector<double>& row) const {
  Vec3 F = Vec3::Zero();  // on the rigid body, at the last evaluation
  for (size_t i = 0; i < nodes_.size(); ++i)
    if (rigid_node_[i]) F += f_now_[i];
  row.insert(row.end(),
             {static_cast<double>(n_active_), penetration_max_, work_, F.x(), F.y(), F.z()});
}

}  // namespace ccm
