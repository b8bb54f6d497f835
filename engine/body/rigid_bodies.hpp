// The rigid bodies of a run as the integrator steps them (docs/rigid-bodies.md). Each body's
// nodes follow its pose: x_i = c + R (X_i - c_0), v_i = V + omega x (x_i - c). The forces the
// step puts on those nodes (loads, contact) and gravity act on the body as a resultant force and
// moment about c, integrated by the kick-drift-kick of rigid_body.hpp in step with the nodes'
// central difference:
//   predict  (after the nodes' predictor)  kick h/2 with F_n, drift h, place the nodes
//   gather   (after the forces of t_{n+1}) F_{n+1} = sum_i f_i + m g, tau = sum_i r_i x f_i
//   finish   (after the nodes' corrector)  the contact's impulses J on the body (a constraint
//            model holds its nodes within the step, engine/contact/contact_model.hpp), then
//            kick h/2 with F_{n+1}; set the nodes' velocities
// A pinned body turns about its pin by the same splitting on its one angle (pinned_motion.hpp).
// A fixed body stays where it is; a prescribed one follows its velocity histories. Both are
// kinematic: a contact model treats their nodes as infinitely heavy, and what it gives them is
// their driver's. A DCR contact holds a pinned body's nodes as anchored too; the body then takes
// the impulses at finish(), as a free one does. Every rigid body's state is written into
// State::rigid.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "engine/body/rigid_body.hpp"
#include "engine/body/rigid_body_model.hpp"
#include "engine/core/held_impulse.hpp"
#include "engine/core/state.hpp"
#include "engine/mesh/model_mesh.hpp"

namespace ccm {

class RigidBodies {
 public:
  RigidBodies(const ModelMesh& mesh, const std::vector<RigidBodyModel>& models);

  bool empty() const { return bodies_.empty(); }
  int size() const { return static_cast<int>(bodies_.size()); }
  const RigidBody& body(int k) const { return bodies_[static_cast<size_t>(k)]; }
  const RigidBodyModel& model(int k) const { return *models_[static_cast<size_t>(k)]; }
  // The resultant force and moment about c at the last gather [N], [N m].
  const Vec3& force(int k) const { return force_[static_cast<size_t>(k)]; }
  const Vec3& torque(int k) const { return torque_[static_cast<size_t>(k)]; }

  // Places every body's nodes at t = 0 with their initial velocities (x = X); sizes s.rigid.
  void initialise(State& s) const;
  // The resultant of s.f on each body's nodes, plus m g, about its current centre; the nodes'
  // accelerations are set to zero (their motion is the body's).
  void gather(State& s, const Vec3& gravity);
  // This step's impulses of a constraint-type contact on the held bodies (one entry per mesh
  // body): taken by the free and pinned bodies at finish().
  void take_impulses(const std::vector<HeldImpulse>& per_body);
  // Between output samples only the bodies' surface nodes move with them (what contact and
  // loads read); place_interior() places the rest, before a sample reads every node.
  void predict(State& s, double dt, double t_n);
  void finish(State& s, double dt);
  void place_interior(State& s) const;

  // Kinetic energy of the free and pinned bodies [J]; work of gravity on them, m g . (c - c_0) [J].
  // A kinematic body's energy is its driver's business and enters neither.
  double kinetic_energy() const;
  double gravity_work(const Vec3& gravity) const;
  // Work of a constraint-type contact's impulses on the free and pinned bodies so far [J]: the
  // kinetic energy each impulse changed. (The only force-type model, the analytic sphere, acts on
  // deformable surfaces alone.)
  double contact_work() const { return contact_work_; }
  // Work of the pins' friction on the pinned bodies so far [J], <= 0.
  double joint_work() const;
  // The pinned motion of body k, or nullptr when it is not pinned.
  const PinnedMotion* pin(int k) const {
    const auto& p = pins_[static_cast<size_t>(k)];
    return p ? &*p : nullptr;
  }
  // Non-empty once a drift has failed (the midpoint iteration did not converge).
  const std::string& failure() const { return failure_; }

 private:
  void place_nodes(int k, State& s, const std::vector<int>& nodes) const;
  void split_nodes(const Body& body);
  void publish(int k, State& s) const;

  const ModelMesh& mesh_;
  std::vector<const RigidBodyModel*> models_;
  std::vector<RigidBody> bodies_;
  std::vector<std::optional<PinnedMotion>> pins_;                 // per body: set for a pinned one
  std::vector<std::vector<int>> surface_nodes_, interior_nodes_;  // per body
  std::vector<Vec3> force_, torque_;  // resultant about c, at the last gather
  std::vector<HeldImpulse> impulse_;  // this step's contact impulses, moments about the origin
  std::vector<Vec3> contact_impulse_, contact_angular_impulse_;  // since t = 0
  double contact_work_ = 0.0;
  std::string failure_;
};

// The nodes of every kinematic (fixed or prescribed) rigid body, sorted: a contact model holds
// them as it holds fixed nodes.
std::vector<int> kinematic_rigid_nodes(const ModelMesh& mesh,
                                       const std::vector<RigidBodyModel>& models);

}  // namespace ccm
