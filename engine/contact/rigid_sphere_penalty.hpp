// The rigid-body contact model of the trade study (thesis 2.8): an analytic rigid sphere (no
// mesh) pushed out of one deformable body's surface by penalty springs (thesis eq. 2.5-2.6;
// docs/equations.md "Rigid-sphere penalty"; docs/contact-method.md §5 "Penalty" and §6(d)).
//
// Where the springs act. The surface's triangles (default "<body>/boundary") carry the
// symmetric 3-point rule of degree 2: barycentric (2/3, 1/6, 1/6) and its two rotations. At each
// quadrature point q, x_q = sum_a N_a(q) x_a on the current configuration, with
//   d = |x_q - x_s| < R:   delta = R - d,   n = (x_q - x_s) / d,
//   f_q = K_P delta n                       on the body           (thesis eq. 2.5, 2.6)
//   f_a += N_a(q) f_q                       to the triangle's nodes (linear shape functions)
//   F_s -= f_q                              on the sphere: equal and opposite
//   E_pen = sum_q 1/2 K_P delta^2           the penalty energy; f = -dE_pen/dx exactly.
//
// Contact damping (optional, `damping` = zeta, a fraction of critical; default 0, the thesis's
// pure spring). A stiff spring against a light surface node is an elastic collision: the node
// leaves the sphere at up to twice the sphere's speed, chatters, and carries four times the
// kinetic energy of a node moving with the sphere. A dashpot in parallel with each spring,
//   f_q = max(0, K_P delta - c_q u_n) n,   u_n = n . (v_q - v_s),  v_q = sum_a N_a(q) v_a,
//   c_q = 2 zeta sqrt(K_P mu_q),   mu_q = m_q m_s / (m_q + m_s),  m_q = sum_a N_a(q) m_a / s_a,
// (the Kelvin-Voigt contact law; the max keeps the contact from pulling) makes that collision
// one of restitution exp(-zeta omega t*) (zeta < 1/sqrt(2), omega^2 = K_P / mu, t* the first zero
// of the force; zeta = 1: none), the inelastic contact of a continuum. u_n uses the
// mid-step velocities v* = v_{n+1/2} the engine holds at add_forces (explicit). The dashpot's
// work is in work() and sphere_work(): the energy balance sees it as dissipated.
//
// How K_P is applied (penalty_mode per_point, the default): K_P [N/m] is the stiffness of ONE
// quadrature point's spring, not scaled by the point's area weight. That is the thesis's model
// (eq. 2.5: "a mechanical spring" K_P per finite location; §2.8: "all quadrature points ... are
// checked", K_P = 1e6 per point), it keeps K_P in N/m, and it makes the stiffness of a contact
// exactly K_P times the number of points inside the sphere. The price, which the thesis paid too:
// the total stiffness of a contact patch grows with the number of points in it, i.e. with mesh
// refinement (about 3 points per triangle in contact). Why 3 points and not the centroid: a 1-point
// rule leaves each node reachable only through triangle centroids, so a small sphere can press
// between centroids and a node's load arrives late and lumpy; with 3 points a point lies at 1/6 of
// the altitude from every edge and carries 2/3 of its force to the nearest node. (The thesis
// checked the volume quadrature points of its artifact; ccm checks the surface, where contact
// happens.)
//
// The sphere is integrated by the engine's own central difference in PEC form (eq. 2.27-2.31):
// begin_step(dt) predicts x_s += dt v_s + dt^2/2 a_s, v_s += dt/2 a_s; add_forces gathers F_s at
// x_{n+1} and sets a_s = F_s / m_s + g; end_step(dt) corrects v_s += dt/2 a_s. Linear momentum of
// sphere + body is therefore conserved to round-off (when no node of the body is fixed).
//
// The element-scaled penalty (penalty_mode element; docs/contact-time-step.md "The
// element-scaled penalty"). Instead of the thesis's K_P per point, surface triangle T gets
//   k_T = s K A_T^2 / V_T   [N/m]   (s = penalty_scale, default 0.1)
// with A_T its reference area, V_T the reference volume of the tet that owns it (T is one of its
// faces) and K = lambda + 2 mu / 3 that tet's bulk modulus at the reference state (LS-DYNA's
// segment-based penalty for solids). Each of T's three points gets k_q = k_T / 3: the rule's
// weights are all A_T / 3, so "k_T / 3" and "k_T times the point's share of the area" are the
// same, and the three sum to k_T. k_T is of order s times the stiffness of the tet behind T, so
// that the springs never limit the step more than the plate itself does (at s = 0.1 the bound
// below stays under the structural one: tested), whatever the mesh or the material. Everything
// above holds with K_P replaced by the point's own k_q (the spring, its energy, the dashpot).
//
// Stable step (docs/contact-time-step.md): omega_pen^2 <= max_a kappa_a / m_a + k_s / m_s with
// kappa_a = sum_q N_a(q) k_q over the points of node a's triangles and k_s the sum of k_q over
// the points that can touch the sphere within the step. Per point (k_q = K_P) that is
// max_a K_P s_a / m_a + K_P n_s / m_s, with s_a = sum_q N_a(q) (= node a's number of surface
// triangles) and n_s the number of points that count; the limit
// returned is sqrt(1 - s^2) * 2 / omega_pen for the engine's structural safety s (0.9: 0.436), so
// that dt^2 (omega_struct^2 + omega_pen^2) <= 4; with damping times sqrt(1 + zeta^2) - zeta, the
// central-difference bound of a damped oscillator (Belytschko, Liu & Moran, Nonlinear Finite
// Elements, section 6.2).
//
// One model object serves one run: it holds the sphere's state.
#pragma once

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "engine/contact/contact_model.hpp"
#include "engine/core/penalty_mode.hpp"
#include "engine/mesh/model_mesh.hpp"
#include "engine/mesh/tet_mesh.hpp"
#include "engine/observe/history.hpp"

namespace ccm {

struct RigidSphere {
  double radius = 0.0;           // R [m], > 0
  double mass = 0.0;             // m_s [kg], > 0
  Vec3 center = Vec3::Zero();    // x_s at t = 0 [m]
  Vec3 velocity = Vec3::Zero();  // v_s at t = 0 [m/s]
};

struct RigidSpherePenaltyParams {
  std::string name = "sphere";  // the history column prefix
  RigidSphere sphere;
  PenaltyMode penalty_mode = PenaltyMode::per_point;
  double penalty = kDefaultPointPenalty;  // per_point: K_P [N/m] per quadrature point (thesis 2.8)
  double penalty_scale = kDefaultElementPenaltyScale;  // element: s > 0
  double damping = 0.0;         // zeta >= 0: the dashpot per point, a fraction of critical
  Vec3 gravity = Vec3::Zero();  // acceleration of the sphere [m/s^2]
  // Unit axis for the history column `<name>.contact_force_axis`; default: the direction of
  // the initial velocity, else of gravity, else -z.
  std::optional<Vec3> force_axis;
};

class RigidSpherePenalty : public ContactModel, public HistorySource {
 public:
  // `surface`: triangles of the deformable body (global node ids), e.g. the surface
  // "<body>/boundary" of the ModelMesh. Throws std::invalid_argument for an empty surface, a
  // radius, mass, penalty or penalty scale that is not > 0, a damping < 0, or a zero force
  // axis. Per point only: the element mode needs the mesh (it throws without it).
  RigidSpherePenalty(std::vector<Triangle> surface, RigidSpherePenaltyParams params);
  // Either mode: `mesh` holds the tets that own the surface's triangles and their materials
  // (read at construction only). Also throws when a triangle is no tet's face.
  RigidSpherePenalty(const ModelMesh& mesh, std::vector<Triangle> surface,
                     RigidSpherePenaltyParams params);

  void begin_step(const State& state, double dt) override;
  void add_forces(State& state) override;
  void correct(State& /*state*/, double /*dt*/) override {}  // a force model: no correction
  // Completes the sphere's velocity and the step's work, and publishes the ledger (the model
  // exchanges energy with the sphere, outside the model: it injects none).
  void end_step(const State& state, double dt) override;
  // The springs' stiffness bound of the points that can act within the step, or the time until
  // the next point can arrive (a kinematic bound); see the .cpp and docs/contact-time-step.md.
  ContactStepBound step_bound(const State& state, double ceiling) const override;
  // Forces only: it moves no node.
  double corrected_elements_stable_dt() const override {
    return std::numeric_limits<double>::infinity();
  }
  // Work of the contact forces on the body's nodes, trapezoidal over each step:
  // sum 1/2 (f_n + f_{n+1}) . (x_{n+1} - x_n) [J].
  double work() const { return work_body_; }

  // History: <name>.sphere_x/y/z, .sphere_vx/vy/vz, .sphere_kinetic_energy, .contact_force
  // (|F_s|), .contact_force_axis (F_s . axis), .penetration_max.
  std::vector<std::string> history_columns() const override;
  void append_history(const State& state, std::vector<double>& row) const override;

  const RigidSpherePenaltyParams& params() const { return params_; }
  const Vec3& sphere_position() const { return x_s_; }
  const Vec3& sphere_velocity() const { return v_s_; }
  const Vec3& sphere_acceleration() const { return a_s_; }
  double sphere_kinetic_energy() const { return 0.5 * params_.sphere.mass * v_s_.squaredNorm(); }
  const Vec3& force_axis() const { return axis_; }
  // Of the last add_forces (at x_{n+1}):
  const Vec3& contact_force() const { return F_s_; }         // on the sphere [N]
  double penalty_energy() const { return penalty_energy_; }  // sum_q 1/2 k_q delta^2 [J]
  // k_q [N/m] of each of the three points of surface triangle tri (in the surface's order).
  double point_stiffness(size_t tri) const { return unit_ * point_weight_[tri]; }
  size_t surface_triangles() const { return tris_.size(); }
  // Work of the dashpots on sphere and body since t = 0 (<= 0) [J]: the energy they took.
  double damping_work() const { return damping_work_; }
  double penetration_max() const { return penetration_max_; }  // max_q delta [m]
  // Non-empty when penetration_max() > kFailureDepth * R: the sphere has sunk half its radius
  // into the surface (K_P far too soft for the impact); see failure() in the .cpp.
  std::string failure() const;
  static constexpr double kFailureDepth = 0.5;
  int active_points() const { return n_active_; }  // points with d < R
  // Work of the contact force on the sphere, trapezoidal like work() [J]. With work():
  // work() + sphere_work() = -(E_pen - E_pen,0) up to the rule's error on nonlinear steps.
  double sphere_work() const { return work_sphere_; }
  // Sorted global ids of the surface's nodes.
  const std::vector<int>& surface_nodes() const { return nodes_; }

 private:
  // mesh: null for the per-point constructor.
  RigidSpherePenalty(const ModelMesh* mesh, std::vector<Triangle> surface,
                     RigidSpherePenaltyParams params);
  std::array<Vec3, 3> corners(const State& state, size_t tri) const;
  // The force of quadrature point k (stiffness k_q) of triangle tri on the body, at depth delta
  // along n (the spring and, with damping, the dashpot); adds the dashpot's power to
  // damping_power_.
  Vec3 point_force(const State& state, size_t tri, int k, double k_q, double delta, const Vec3& n);
  // sqrt(1 - s^2) * 2 / omega_pen for omega_pen^2 = node_term + unit_ weight_sum / m_s, where
  // node_term = max_a kappa_a / m_a over the nodes that can be pushed and weight_sum is the sum
  // of point_weight_ over the points that count.
  double limit_from(double node_term, double weight_sum) const;
  double node_term(const State& state, int tri) const;

  RigidSpherePenaltyParams params_;
  std::vector<int> nodes_;                // global ids of the surface nodes
  std::vector<std::array<int, 3>> tris_;  // local node indices (into nodes_)
  std::vector<double> valence_;           // s_a = sum_q N_a(q) = surface triangles at a
  // k_q = unit_ point_weight_[tri] and kappa_a = unit_ node_weight_[a]. Per point: unit_ = K_P,
  // point weight 1 and node weight s_a, so that every product is the one the thesis's model
  // always computed (bit for bit). Element: unit_ = 1 N/m, point weight k_T / 3.
  double unit_ = 0.0;
  std::vector<double> point_weight_;  // per triangle
  std::vector<double> node_weight_;   // per surface node: sum_q N_a(q) point_weight
  Vec3 axis_ = -Vec3::UnitZ();

  // Sphere state (t_n before the predictor, t_{n+1} after it).
  Vec3 x_s_ = Vec3::Zero(), v_s_ = Vec3::Zero(), a_s_ = Vec3::Zero();
  Vec3 x_s_n_ = Vec3::Zero();  // position at the start of the step

  // Nodal contact forces of the last two evaluations (local index), and their support.
  std::vector<Vec3> f_np1_, f_n_;
  std::vector<int> touched_np1_, touched_n_;
  std::vector<char> is_touched_np1_, is_touched_n_;
  std::vector<Vec3> x_n_;  // surface node positions at the start of the step
  Vec3 F_s_ = Vec3::Zero(), F_s_n_ = Vec3::Zero();

  double penalty_energy_ = 0.0;
  double penetration_max_ = 0.0;
  int n_active_ = 0;
  double work_body_ = 0.0;
  double work_sphere_ = 0.0;
  double damping_power_ = 0.0, damping_power_n_ = 0.0;  // of the last two evaluations [W]
  double damping_work_ = 0.0;
  double damping_bound_factor_ = 1.0;  // sqrt(1 + zeta^2) - zeta

  // |x_q - x_s|^2 of every point (3 per triangle), as add_forces last computed them on the
  // state d2_of_ at time d2_t_ (null when they are not add_forces's: after begin_step, as the
  // sphere moves, or after step_bound recomputed them for another state). step_bound
  // reuses them for that state and time: the engine does not move the nodes between the two.
  mutable std::vector<double> d2_;
  mutable const State* d2_of_ = nullptr;
  double d2_t_ = 0.0;
  mutable std::vector<std::pair<double, int>> scratch_;  // step_bound: (d^2, triangle)
};

}  // namespace ccm
