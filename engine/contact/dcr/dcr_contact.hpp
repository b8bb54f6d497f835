// Explicit Decomposition Contact Response (DCR; Cirak & West 2005; thesis 2.4, eq. 2.10-2.26),
// node-face and edge-edge, external and self-contact.
//
// Each step, after the internal forces are evaluated (thesis 2.5.2):
//   1. detect: swept-box broad phase over [x_n, x*] and continuous collision detection of every
//      candidate pair; each hit becomes a constraint g(x) >= 0, g the signed volume of the
//      node and face (or the two edges), oriented so that the start of the step is admissible;
//   2. impenetrability: a mass-weighted projection along grad g (linear and angular momentum
//      conserved exactly, contact-method.md 1.2), iterated Jacobi-style with per-node averaging
//      until every constraint holds, so the result does not depend on the order of contacts;
//   3. momentum decomposition: the normal part of the end-of-step velocity along grad g is
//      reversed and scaled by the restitution e (e = 1: eq. 2.26; e = 0: removed), again by
//      Jacobi iterations on non-negative impulses; then Coulomb friction reduces the tangential
//      relative velocity of each contact by at most mu times its normal impulse.
// The velocity change is applied to v* so that v_{n+1} = v* + dt/2 a_{n+1} satisfies it.
#pragma once

#include <string>
#include <vector>

#include "engine/contact/contact_model.hpp"
#include "engine/contact/dcr/broad_phase.hpp"
#include "engine/contact/dcr/contact_surface.hpp"
#include "engine/observe/history.hpp"

namespace ccm::dcr {

struct DcrSettings {
  std::vector<std::string> surfaces;  // named surfaces that take part, e.g. "ball/boundary"
  bool self_contact = false;          // contacts within one body too (adjacent pairs excluded)
  double restitution = 0.0;           // e in [0, 1]
  double friction = 0.0;              // Coulomb mu >= 0
  int max_iterations = 100;           // Jacobi sweeps for positions and for velocities
  double step_fraction = 0.5;         // dt limit: relative motion per step <= this x min edge
};

// One active contact: g(x) = sign * volume(nodes) >= target.
struct Constraint {
  std::array<int, 4> nodes;  // node-face: p, a, b, c; edge-edge: a, b, c, d (global ids)
  bool node_face = true;
  double sign = 1.0;
  double approach_rate = 0.0;  // dg/dt when detected (< 0 when approaching)
  double impulse = 0.0;        // accumulated normal multiplier of the velocity solve
};

class DcrContact : public ContactModel, public HistorySource {
 public:
  // fixed_nodes: nodes held by boundary conditions; the contact never moves them.
  DcrContact(const ModelMesh& mesh, DcrSettings settings, const std::vector<int>& fixed_nodes);

  std::string_view name() const override { return "dcr"; }
  void begin_step(const State& state, double dt) override;
  void correct(State& state, double dt) override;
  double stable_dt_limit(const State& state) const override;
  double work() const override { return work_; }
  // Non-empty when the projection left a penetration deeper than kFailurePenetration times the
  // shortest surface edge (the iterations did not converge: the contact no longer holds).
  std::string failure() const override;
  static constexpr double kFailurePenetration = 1e-3;

  std::vector<std::string> history_columns() const override;
  void append_history(const State& s, std::vector<double>& row) const override;

  // Diagnostics of the last step.
  int active_contacts() const { return static_cast<int>(constraints_.size()); }
  double residual_penetration() const { return residual_; }  // max -g/|grad_p g| [m], >= 0
  const SurfaceFeatures& features() const { return features_; }
  double min_edge() const { return min_edge_; }  // shortest surface edge, reference [m]

 private:
  void detect(const State& s);
  bool bodies_may_touch(const State& s) const;
  void project_positions(State& s);
  void exchange_momentum(State& s, double dt);
  void apply_friction(const State& s, std::vector<Vec3>& v_end);
  void apply_relaxed(std::vector<Vec3>& target);
  double mobility(const Constraint& c, const std::array<Vec3, 4>& grad) const;
  double rate_of(const Constraint& c, const std::array<Vec3, 4>& grad,
                 const std::vector<Vec3>& v) const;
  double constraint_value(const Constraint& c, const std::vector<Vec3>& x) const;
  double constraint_gradient(const Constraint& c, const std::vector<Vec3>& x, Vec3 grad[4]) const;

  DcrSettings settings_;
  SurfaceFeatures features_;
  BroadPhase broad_phase_;
  Candidates candidates_;
  std::vector<double> inv_m_;  // 1/m of every node; 0 for fixed nodes
  std::vector<Vec3> x_n_;      // positions at the start of the step
  double min_edge_ = 0.0;      // shortest surface edge in the reference configuration
  double separation_ = 0.0;    // distance kept between a node and a face after projection
  std::vector<Constraint> constraints_;
  std::vector<int> count_;                  // scratch: constraints per node in a sweep
  std::vector<double> steps_;               // scratch: proposed multiplier step per constraint
  std::vector<std::array<Vec3, 4>> grads_;  // scratch: grad g per constraint
  std::vector<Vec3> tangent_;               // scratch: friction directions
  std::vector<Vec3> x_start_, v_before_;    // scratch: state before the correction
  std::vector<Vec3> v_end_;                 // scratch: end-of-step velocities of constrained nodes
  double work_ = 0.0;
  double residual_ = 0.0;
  double last_impulse_ = 0.0;  // total normal impulse magnitude of the last step
};

}  // namespace ccm::dcr
