// The hook through which a contact model acts on an explicit step (thesis 2.5.2). A scene
// without contact passes no model at all and pays nothing: no search, no surface data.
//
// Order within a step (engine/solver/explicit_integrator.hpp):
//   begin_step (x_n, v_n known)  ->  predict  ->  add_forces (into f, before a = M^-1 f)
//   ->  accelerations  ->  correct (x_{n+1}, v*)  ->  boundary conditions  ->  v correction
//   ->  end_step.
//
// Five pure virtual methods (and two optional hooks, use_replica_team and add_held_impulses): a
// model that leaves one out does not compile (tests/engine/contact/test_contact_interface.cpp).
// The name, the phases and the ledger are data of this base class, given at construction or kept
// current by the model, so a wrapper has nothing to forward and no caller restates per model what
// it does (docs/architecture.md).
#pragma once

#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "engine/contact/replica_team.hpp"
#include "engine/core/held_impulse.hpp"
#include "engine/core/state.hpp"

namespace ccm {

// What a contact model allows of the next step, WITHOUT any safety factor: the integrator owns
// the one safety factor s = TimeControl::dt_safety (docs/contact-time-step.md, "One safety
// factor"). The step taken is
//   dt = min( s (dt_s^-2 + stiffness_dt^-2)^(-1/2),  kinematic_dt )          (CT.1)
// with dt_s the elements' stable step: the contact's springs add their squared frequency to the
// structure's (omega_max^2 <= omega_s^2 + omega_k^2 for a sum of stiffnesses on one mass matrix),
// and a kinematic bound caps the step outright.
struct ContactStepBound {
  // 2 / omega_max of the stiffness the model adds (penalty springs, with any damping reduction).
  double stiffness_dt = std::numeric_limits<double>::infinity();
  // The longest step for which the model's detection stays valid (e.g. no point can arrive
  // unseen, or no feature can pass another within the step).
  double kinematic_dt = std::numeric_limits<double>::infinity();
};

// Which phases of a step a model acts in: penalty-type models add forces (add_forces), constraint
// types correct positions and velocities (correct). A partitioned run replicates only those
// (engine/distributed/replicated_contact.hpp); a set of models acts in the union of its members'.
struct ContactPhases {
  bool adds_forces = false;
  bool corrects = false;
};
inline constexpr ContactPhases kForcePhases{.adds_forces = true, .corrects = false};
inline constexpr ContactPhases kCorrectionPhases{.adds_forces = false, .corrects = true};

// The ceiling that asks for a model's kinematic bound whatever its value
// (ContactModel::step_bound).
inline constexpr double kNoStepCeiling = std::numeric_limits<double>::infinity();

// What a model has done so far, for the energy balance and the verdict.
struct ContactLedger {
  // Work done on the deformable bodies by the contact [J].
  double work = 0.0;
  // The part of the work the model's physics does not allow [J], >= 0: a model whose contacts can
  // only dissipate reports its net positive work; one that exchanges energy with something
  // outside the model (a rigid sphere's kinetic energy) reports 0. The monitor ends a run when
  // it exceeds the energy tolerance.
  double injected_energy = 0.0;
  // True when the model acted on some node in the last step (a force or a correction): the
  // bodies touch. A run may end once it has been false for a hold time (TimeControl).
  bool touching = false;
  // Non-empty when the contact has failed in the last step (the reason, for the verdict): the run
  // then ends unstable. Checked by the integrator after every step.
  std::string failure;
};

class ContactModel {
 public:
  ContactModel(std::string name, ContactPhases phases) : name_(std::move(name)), phases_(phases) {}
  virtual ~ContactModel() = default;
  ContactModel(const ContactModel&) = delete;
  ContactModel& operator=(const ContactModel&) = delete;

  const std::string& name() const { return name_; }
  const ContactPhases& phases() const { return phases_; }
  const ContactLedger& ledger() const { return ledger_; }

  // Called with the state at t_n before the predictor of a step of size dt.
  virtual void begin_step(const State& state, double dt) = 0;
  // Penalty-type models add their forces on the nodes into state.f (at x_{n+1}).
  virtual void add_forces(State& state) = 0;
  // Constraint-type models correct x_{n+1} and the predicted velocities v* (thesis 2.5.2).
  virtual void correct(State& state, double dt) = 0;
  // Called after the velocity correction; v holds v_{n+1}. The ledger is current after it.
  virtual void end_step(const State& state, double dt) = 0;
  // The bound on the next step from this state, without safety factor (eq. CT.1). `ceiling` is
  // the step the engine takes without the contact's kinematic bound: a kinematic_dt at or above
  // it does not change the step, so a model may return infinity instead of computing it.
  virtual ContactStepBound step_bound(const State& state, double ceiling) const = 0;
  // The structure's stable step (without safety factor) of the elements whose nodes correct()
  // moved, at their corrected positions; infinite when it moved none. The element kernel measured
  // the structure's step before the correction, so the next step takes the smaller of the two.
  // A model that moves no node (a force model) returns infinity; a model that wraps others
  // forwards it (pure, so that none forgets).
  virtual double corrected_elements_stable_dt() const = 0;

  // A partitioned run offers its team to the replicated model (replica_team.hpp): for whole
  // bodies and for loops split among the ranks. A model that reads only its contact surfaces and
  // the elements touching them, and splits nothing, ignores it. Not pure for that reason.
  virtual void use_replica_team(ReplicaTeam& /*team*/) {}

  // Adds this step's impulses on held bodies into per_body (one entry per body of the mesh);
  // called after correct(). A model that acts by forces (add_forces) adds nothing: its forces on
  // a rigid body's nodes reach the body through the nodal forces. Not pure for that reason.
  virtual void add_held_impulses(std::vector<HeldImpulse>& /*per_body*/) const {}

 protected:
  ContactLedger ledger_;

 private:
  std::string name_;
  ContactPhases phases_;
};

}  // namespace ccm
