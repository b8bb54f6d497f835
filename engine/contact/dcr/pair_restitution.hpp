// Body-pair restitution (docs/contact-restitution.md): the coefficient of restitution e a user
// knows from a drop test, applied to a contact episode between two bodies, not to a node.
//
// The constraint-level response is always inelastic (e = 0 per contact, docs/contact-method.md
// §1.5): the rebound of a continuum comes from its elastic waves, and a deformable sphere so
// rebounds at nearly its impact speed. That elastic rebound is the e = 1 result. For e < 1, when
// the two bodies separate, Newton's law for the episode is enforced on their rigid-body motions
// (the mass- weighted mean velocity and rotation of each body, eq. R1 of the note):
//   u = n . (v_B(P) - v_A(P)),  v_X(P) = v_cm,X + omega_X x (P - c_X),
// with P and n the impulse-weighted contact point and normal direction of the episode (an episode
// lasts from the first step with a normal impulse between the bodies to the first step in which
// they hold no contact, persistent ones included). With u_in
// the value when the episode began (u_in < 0, approaching) and u_out at separation, a separating
// u_out > -e u_in is reduced to -e u_in by the impulse pair -j n on B, +j n on A at P (eq. R2):
//   j = (u_out + e u_in) / K,  K = 1/m_A + 1/m_B + n . ((I_A^-1 (r_A x n)) x r_A + same for B),
// applied as a rigid velocity change of every node of each body. Linear and angular momentum are
// exact (equal and opposite impulses at one point); the kinetic energy only decreases (j > 0
// reduces a separating speed to a smaller separating one); e = 1 never acts unless the elastic
// result rebounds faster than it arrived. A body with fixed nodes is anchored: infinite mass,
// never changed. Contacts within one body (self-contact) have no restitution beyond e = 0.
#pragma once

#include <Eigen/Geometry>  // cross
#include <iterator>
#include <map>
#include <utility>
#include <vector>

#include "engine/contact/replica_team.hpp"
#include "engine/core/state.hpp"
#include "engine/core/types.hpp"
#include "engine/mesh/model_mesh.hpp"

namespace ccm::dcr {

// The rigid-body part of one (deformable) body's motion: mass, centre, velocity of the centre,
// angular velocity, and the inverse inertia about the centre.
struct BodyRigidPart {
  double mass = 0.0;
  Vec3 centre = Vec3::Zero(), velocity = Vec3::Zero(), omega = Vec3::Zero();
  Mat3 inv_inertia = Mat3::Zero();
  Vec3 velocity_at(const Vec3& p) const { return velocity + omega.cross(p - centre); }
};

// One step's normal impulse between bodies A < B: the impulse on B (N s, a vector) and where
// it acts.
struct PairImpulse {
  int body_a = 0, body_b = 0;
  Vec3 impulse_on_b = Vec3::Zero();
  Vec3 point = Vec3::Zero();
};

class PairRestitution {
 public:
  // anchored[b]: body b holds a fixed node.
  PairRestitution(const ModelMesh& mesh, double restitution, std::vector<bool> anchored);

  // The end-of-step velocity of a node during the contact correction is v* + dt/2 a_{n+1}.
  // Before the contact solve of a step: records the incoming motion of every pair in `near`
  // (bodies with a contact candidate, A < B) whose episode has not begun.
  void before_solve(const std::vector<std::pair<int, int>>& near, const State& s, double dt);
  // After the solve (s.v holds the solved v*): `touching` holds this step's impulses, `near`
  // (sorted) the pairs that hold any contact. Episodes begin at a touching step, accumulate, and
  // end at the first step in which the pair holds no contact at all; an ending episode's correction
  // is added to s.v (rigid velocity changes). Returns the kinetic energy change of the corrections
  // [J] (<= 0).
  double after_solve(const std::vector<PairImpulse>& touching,
                     const std::vector<std::pair<int, int>>& near, State& s, double dt);

  // A partitioned run's team (replica_team.hpp), asked for the nodes beyond the contact region
  // before every read of a whole body.
  void use_replica_team(ReplicaTeam& team) { team_ = &team; }

  int corrections() const { return corrections_; }  // episodes corrected so far
  // The corrections of the last after_solve: the impulse on B of each pair corrected.
  const std::vector<PairImpulse>& last_corrections() const { return last_; }
  // The kinetic energy the last after_solve's impulses give free and pinned rigid bodies (which
  // take them at the end of the step): not in its return value, whose work the nodes did; the
  // rigid bodies book theirs themselves (engine/body/rigid_bodies.hpp).
  double last_rigid_energy() const { return rigid_energy_; }

 private:
  struct Episode {
    BodyRigidPart a_in, b_in;     // motions when the episode began
    Vec3 impulse = Vec3::Zero();  // accumulated impulse on B
    Vec3 weighted_point = Vec3::Zero();
    double weight = 0.0;
    bool started = false;  // a touching step has been seen
    bool touched = false;  // touching in the current step
  };
  BodyRigidPart motion_of(int body, const State& s, double dt) const;
  void need_whole_bodies() const {
    if (team_) team_->make_whole_bodies_current();
  }
  // Ends the episode if the bodies separate; returns false while they still approach.
  bool close(const Episode& ep, int a, int b, State& s, double dt, double& energy_change);
  // Applies the impulse at `point` to body `body` as a rigid velocity change; returns the
  // kinetic energy change.
  double apply_rigid_impulse(int body, const BodyRigidPart& motion, const Vec3& impulse,
                             const Vec3& point, State& s, double dt) const;

  struct NodeRange {
    int first, count;
  };
  std::vector<NodeRange> bodies_;  // nodes of every body
  double e_;
  std::vector<bool> anchored_;
  std::map<std::pair<int, int>, Episode> episodes_;  // ordered: deterministic
  int corrections_ = 0;
  std::vector<PairImpulse> last_;
  double rigid_energy_ = 0.0;
  ReplicaTeam* team_ = nullptr;
};

}  // namespace ccm::dcr
