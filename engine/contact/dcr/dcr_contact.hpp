// Explicit Decomposition Contact Response (DCR; Cirak & West 2005; thesis 2.4, eq. 2.10-2.26),
// node-face and edge-edge, external and self-contact (docs/contact-persistent.md).
//
// Each step, after the internal forces are evaluated (thesis 2.5.2):
//   1. detect: swept-box broad phase over [x_n, x*] inflated by the proximity distance, and
//      (a) continuous collision detection of every candidate pair: each hit is a contact;
//      (b) persistent contacts: a node that is on the outward side of a face at both ends of
//      the step, within the proximity distance of it at the end, with its projection inside
//      the face. Each contact is a constraint g(x) >= 0, g the signed volume of the node and
//      face (or the two edges), oriented so that the start of the step is admissible;
//   2. impenetrability: a mass-weighted projection along grad g onto g >= g_sep (linear and
//      angular momentum conserved exactly, docs/contact-method.md §1.2), symmetric Gauss-Seidel
//      sweeps in an order fixed by the geometry (never by node numbers or search order) until
//      every constraint holds; then the forces of the elements around the moved nodes are
//      re-evaluated and the stored energy they gained is booked (projection_update.hpp);
//   3. momentum decomposition (contact_impulses.hpp): on the end-of-step velocity v* + dt/2 a,
//      each contact may approach at most by its remaining gap in the next step
//      (dg/dt >= -(g - g_sep)/dt; 0 once closed: e = 0 per constraint, docs/contact-method.md
//      §1.5), with Coulomb friction iterated together with the normal impulses; a contact that
//      the known acceleration a_{n+1} presses shut is held so that the next predictor lands it
//      above the kept separation (make_row; docs/hard-scenes.md, "Resting contact");
//   4. restitution (pair_restitution.hpp): the user's coefficient e acts on the rigid motions
//      of the two bodies when a contact episode ends.
// The velocity change is applied to v* so that v_{n+1} = v* + dt/2 a_{n+1} satisfies it.
#pragma once

#include <algorithm>
#include <array>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "engine/contact/contact_model.hpp"
#include "engine/contact/dcr/broad_phase.hpp"
#include "engine/contact/dcr/contact_impulses.hpp"
#include "engine/contact/dcr/contact_output.hpp"
#include "engine/contact/dcr/contact_surface.hpp"
#include "engine/contact/dcr/edge_orientation.hpp"
#include "engine/contact/dcr/pair_distance_cache.hpp"
#include "engine/contact/dcr/pair_restitution.hpp"
#include "engine/contact/dcr/projection_update.hpp"
#include "engine/contact/dcr/step_limit.hpp"
#include "engine/contact/dcr/thread_chunks.hpp"
#include "engine/observe/history.hpp"

namespace ccm::dcr {

struct DcrSettings {
  std::vector<std::string> surfaces;  // named surfaces that take part, e.g. "ball/boundary"
  bool self_contact = false;          // contacts within one body too (adjacent pairs excluded)
  double restitution = 0.0;           // e in [0, 1], per pair of bodies (pair_restitution.hpp)
  double friction = 0.0;              // Coulomb mu >= 0
  int max_iterations = 100;           // Gauss-Seidel sweeps of the velocity solve
  // Gauss-Seidel sweeps of the position projection (per round of re-detection).
  int max_projection_iterations = 400;
  double step_fraction = 0.5;   // dt limit: a pair's approach per step <= gap + this x its edge
  double proximity = 0.1;       // persistent contacts: gap <= this x min edge
  ContactOutputRequest output;  // pair forces and sensor pressures, when asked
  std::string history_prefix = "contact";  // of the history columns: "<prefix>.active", ...
  // Threads of the detection (swept boxes, broad phase, CCD, the bodies' reach): the result is
  // the same for any count (thread_chunks.hpp). The solves run on one thread.
  ThreadUse threads;
};

// One active contact: g(x) = sign * volume(nodes) >= target.
struct Constraint {
  std::array<int, 4> nodes;  // node-face: p, a, b, c; edge-edge: a, b, c, d (global ids)
  bool node_face = true;
  double sign = 1.0;
  bool projected = false;  // moved by the position projection in this step
};

class DcrContact : public ContactModel, public HistorySource {
 public:
  // fixed_nodes: nodes the contact holds without moving them: those of boundary conditions and
  // every node of a rigid body (engine/body/), which moves as its body does; a body holding one is
  // anchored (infinite mass) for the restitution, and the impulses on it are reported by
  // add_held_impulses.
  DcrContact(const ModelMesh& mesh, DcrSettings settings, const std::vector<int>& fixed_nodes);

  void begin_step(const State& state, double dt) override;
  void add_forces(State& /*state*/) override {}  // a constraint model: no forces
  void correct(State& state, double dt) override;
  // Publishes the ledger (work, injected energy, failure) of the step.
  void end_step(const State& state, double dt) override;
  // A kinematic bound only, per candidate pair (docs/contact-time-step.md, "DCR").
  ContactStepBound step_bound(const State& state, double ceiling) const override;
  // The stable step of the elements around the nodes this step's projection moved, there
  // (projection_update.hpp).
  double corrected_elements_stable_dt() const override { return projected_stable_dt_; }
  // A partitioned run's team: whole bodies for the restitution; the loops over the surface nodes
  // (the bodies' boxes and reach, the broad phase's sweep) split among the ranks.
  void use_replica_team(ReplicaTeam& team) override;
  // The step's impulses on held nodes (the rows' lambda_n grad_a + beta_a lambda_t) and the
  // restitution's on anchored bodies, per body.
  void add_held_impulses(std::vector<HeldImpulse>& per_body) const override;
  // Work on the bodies so far, but for the stored energy this step's projection put into the
  // elements: the integrator measured the stored energy before the contact moved any node, so
  // that part enters its balance with the next evaluation (the kinetic part of the projection,
  // dt/2 v* . df, it sees in this step; the history column contact.work has it all).
  double work() const { return work_ - projection_stored_; }
  // Every DCR contact is between bodies of the model and can only dissipate (inelastic
  // constraints, dissipative restitution and friction): net positive work is injected. The
  // constraints' work (projection and impulses, which hand the impact energy back and forth
  // between them from one step to the next: 5x the impact energy each way on the coarse Hertz
  // test, docs/contact-time-step.md) is netted over the run, but never against the
  // restitution's dissipation, which is counted apart.
  double injected_energy() const {
    return std::max(0.0, parts_.projection + parts_.impulses) + std::max(0.0, parts_.restitution);
  }
  // Non-empty when the projection left a penetration deeper than kFailurePenetration times the
  // shortest surface edge (the iterations did not converge: the contact no longer holds).
  std::string failure() const;
  static constexpr double kFailurePenetration = 1e-3;
  // Rounds of projection and re-detection of what the projection pushed through.
  static constexpr int kDetectionRounds = 4;

  std::vector<std::string> history_columns() const override;
  void append_history(const State& s, std::vector<double>& row) const override;

  // Diagnostics of the last step: contacts that acted (projected or carried a normal impulse),
  // and all contacts held (acting or within the proximity distance).
  int active_contacts() const { return active_; }
  int held_contacts() const { return static_cast<int>(constraints_.size()); }
  int solver_sweeps() const { return sweeps_; }  // Gauss-Seidel sweeps of the velocity solve
  // Solves that stopped at their sweep cap without meeting their tolerance, since the start:
  // velocity solves (max_iterations) and position projections (max_projection_iterations in a
  // round). The run goes on (momentum stays exact, the work stays booked, the next step's
  // projection takes up what is left; a projection that leaves a penetration deeper than
  // kFailurePenetration ends it, failure()); the summary reports them as a warning.
  // The work so far [J] by mechanism: the position projection (dQ + dK, projection_update.hpp),
  // the normal and friction impulses, the pair restitution. Their sum is the contact's work.
  struct WorkParts {
    double projection = 0.0, impulses = 0.0, restitution = 0.0;
  };
  const WorkParts& work_parts() const { return parts_; }
  long unconverged_velocity_solves() const { return unconverged_velocity_; }
  long unconverged_projections() const { return unconverged_projection_; }
  // The broad phase's work so far: searched steps, pair-cache rebuilds, cached pairs.
  const BroadPhaseStats& broad_phase_stats() const { return broad_phase_.stats(); }
  // Steps in which the position projection moved a node (diagnostics: resting contact aims to
  // leave it nothing to do, make_row).
  long projecting_steps() const { return projecting_steps_; }
  const PairRestitution& restitution() const { return restitution_; }
  double residual_penetration() const { return residual_; }  // max -g/|grad_p g| [m], >= 0
  const SurfaceFeatures& features() const { return features_; }
  // Detection loops that ran on more than one thread since construction.
  long threaded_loops() const { return loops_.threaded_loops(); }
  double min_edge() const { return min_edge_; }  // shortest surface edge, reference [m]

 private:
  void detect(const State& s);
  int test_candidates(const State& s, bool only_touched);
  // cache: the pair distances kept over steps (null: test in full).
  std::optional<Constraint> candidate_contact(const State& s, size_t k,
                                              PairDistanceCache* cache) const;
  bool candidate_touched(size_t k) const;
  int redetect(const State& s);
  void remember_start(const State& s, size_t first);
  void enforce_positions(State& s, double dt);
  // k: the candidate's index, for the cache (may be null).
  std::optional<Constraint> node_face_contact(const State& s, int p, const Triangle& t, size_t k,
                                              PairDistanceCache* cache) const;
  bool persists_within_proximity(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) const;
  // edge_a, edge_b: indices into features_.edges.
  std::optional<Constraint> edge_edge_contact(const State& s, int edge_a, int edge_b, size_t k,
                                              PairDistanceCache* cache) const;
  bool bodies_may_touch(const State& s) const;
  bool project_positions(State& s);
  void exchange_momentum(State& s, double dt);
  // distance: the constraint's signed distance g / |grad_p g| at x (the residual's measure).
  ContactRow make_row(const Constraint& c, const std::vector<Vec3>& x, const std::vector<Vec3>& acc,
                      double dt, double& distance) const;
  void collect_pair_impulses(const std::vector<Vec3>& x);
  void collect_held_impulses(const State& s);
  void order_constraints();
  double mobility(const Constraint& c, const std::array<Vec3, 4>& grad) const;
  double constraint_value(const Constraint& c, const std::vector<Vec3>& x) const;
  double constraint_gradient(const Constraint& c, const std::vector<Vec3>& x, Vec3 grad[4]) const;
  int body_of(int node) const { return node_body_[static_cast<size_t>(node)]; }

  DcrSettings settings_;
  SurfaceFeatures features_;
  ChunkedLoops loops_;
  EdgeOrientation edge_orientation_;  // the admissible side of edges that start in one plane
  BroadPhase broad_phase_;
  Candidates candidates_;
  PairDistanceCache distances_;                // the candidates' start distances kept over steps
  std::vector<char> candidate_is_constraint_;  // per candidate (node-face, then edge-edge)
  ChunkLists<Constraint> found_;               // scratch: new constraints per chunk of candidates
  std::vector<double> inv_m_;                  // 1/m of every node; 0 for fixed nodes
  std::vector<int> node_body_;                 // body of every node
  size_t n_bodies_ = 0;
  ReplicaTeam* team_ = nullptr;  // of a partitioned run; null in a serial one
  std::vector<Vec3> x_n_;        // positions at the start of the step
  double min_edge_ = 0.0;        // shortest surface edge in the reference configuration
  double separation_ = 0.0;      // distance kept between a node and a face after projection
  double proximity_ = 0.0;       // distance within which a node-face contact persists
  std::vector<Constraint> constraints_;
  std::vector<ContactRow> rows_;
  ContactImpulses impulses_;
  PairRestitution restitution_;
  ProjectionUpdate projection_update_;
  double projected_stable_dt_ = std::numeric_limits<double>::infinity();
  // The next step's bound from the last projection's largest move (step_bound, eq. PJ.1).
  double projection_jump_dt_ = std::numeric_limits<double>::infinity();
  ContactOutput output_;
  std::vector<PairImpulse> pair_impulses_;  // scratch: this step's impulses per body pair
  std::vector<bool> anchored_;              // per body: holds a held node
  std::vector<HeldImpulse> held_;           // this step's impulses on held nodes, per body
  RigidPartners partners_;                  // the free rigid bodies, for the velocity solve
  std::vector<std::pair<int, int>> near_;   // scratch: body pairs holding contacts
  std::vector<int> count_;                  // scratch: per-node marks (all zero between uses)
  using ConstraintKey = std::array<double, 7>;
  std::vector<ConstraintKey> keys_;  // scratch: geometric key per constraint
  std::vector<int> order_;           // the constraints in the order of their keys
  // The constraints order_ is of (nodes, node_face).
  std::vector<std::pair<std::array<int, 4>, bool>> ordered_;
  std::vector<Vec3> X_;                   // reference positions
  ReferenceLengths lengths_;              // of the surface's faces and edges (step limit)
  std::vector<Vec3> x_start_, v_before_;  // scratch: state before the correction
  std::vector<int> moved_;                // scratch: nodes of the constraints of the step
  std::vector<char> touched_;             // scratch: per node, moved by the projection
  std::vector<Vec3> v_end_;               // scratch: end-of-step velocities of constrained nodes
  double work_ = 0.0;
  double projection_stored_ = 0.0;  // dQ of this step's projection (included in work_)
  WorkParts parts_;
  long unconverged_velocity_ = 0, unconverged_projection_ = 0;
  long projecting_steps_ = 0;
  double residual_ = 0.0;
  double last_impulse_ = 0.0;  // total normal impulse of the last step [N s]
  int active_ = 0;
  int sweeps_ = 0;
  double previous_dt_ = 0.0;  // the length of the last step (make_row's resting aim)
};

}  // namespace ccm::dcr
