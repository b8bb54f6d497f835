// The contact models of one run, one per contact pair or group of pairs ([[contact.pairs]],
// docs/scene-file.md), acting on a step as one model does: in the order given, each in its
// own phases. The integrator and a partitioned run see one ContactModel; nothing restates per
// member what it does.
//
// Within a step every member's add_forces adds into f (penalty forces sum), and every member's
// correct() acts after the previous member's on the corrected x_{n+1} and v* (constraints are
// met in order; two constraint models that share nodes are grouped into one model by the scene
// builder instead, so that one solve sees all of their constraints).
//
// The step bound: the members' added stiffnesses act on one mass matrix, so their squared
// frequencies add (omega^2 <= sum_i omega_i^2, the bound of eq. CT.1 applied to a sum of
// springs), which is 1/dt^2 = sum_i 1/dt_i^2 for the stiffness steps; the kinematic bound is
// the smallest of the members'.
#pragma once

#include <memory>
#include <vector>

#include "engine/contact/contact_model.hpp"

namespace ccm {

class ContactSet final : public ContactModel {
 public:
  // members: at least one; the set's name joins theirs with " + ". Throws std::invalid_argument
  // for an empty list or a null member.
  explicit ContactSet(std::vector<std::unique_ptr<ContactModel>> members);

  void begin_step(const State& state, double dt) override;
  void add_forces(State& state) override;
  void correct(State& state, double dt) override;
  // The ledger: the members' work and injected energy summed; the first member's failure, in
  // member order, named by that member.
  void end_step(const State& state, double dt) override;
  ContactStepBound step_bound(const State& state, double ceiling) const override;
  double corrected_elements_stable_dt() const override;  // the members' smallest
  void use_replica_team(ReplicaTeam& team) override;
  void add_held_impulses(std::vector<HeldImpulse>& per_body) const override;

  const std::vector<std::unique_ptr<ContactModel>>& members() const { return members_; }

 private:
  std::vector<std::unique_ptr<ContactModel>> members_;
};

}  // namespace ccm
