// The contact impulse each surface node received, whatever the contact model: a ContactModel
// decorator that forwards every hook to the model it wraps (and takes its ledger, the figures
// the monitor reads) and measures, on the listed nodes,
//   - a constraint-type model (DCR, thesis 2.4): the momentum its correction gave,
//       I_i += m_i (v_i,after - v_i,before)                       (as the rig's sensor, 3.3.3);
//   - a penalty-type model: the force it added, integrated as the central difference does,
//       I_i += dt_n / 2 (f_i,n + f_i,n+1)                           (eq. 2.31: v_n+1 = v_n +
//       dt/2 (a_n + a_n+1)), so that the sum of I_i is the momentum the contact gave.
// The wrapped model is not touched: no accessor into it is needed.
#pragma once

#include <vector>

#include "engine/contact/contact_model.hpp"

namespace ccm::fields {

class ContactImpulseProbe : public ContactModel {
 public:
  // `inner` is not owned and must outlive the probe; `nodes` are global node ids.
  ContactImpulseProbe(ContactModel& inner, std::vector<int> nodes);

  void begin_step(const State& s, double dt) override;
  void add_forces(State& s) override;
  void correct(State& s, double dt) override;
  // The inner model's ledger becomes the probe's (the monitor's checks read it).
  void end_step(const State& s, double dt) override {
    inner_.end_step(s, dt);
    ledger_ = inner_.ledger();
  }
  ContactStepBound step_bound(const State& s, double ceiling) const override {
    return inner_.step_bound(s, ceiling);
  }
  double corrected_elements_stable_dt() const override {
    return inner_.corrected_elements_stable_dt();
  }
  void use_replica_team(ReplicaTeam& team) override { inner_.use_replica_team(team); }
  void add_held_impulses(std::vector<HeldImpulse>& per_body) const override {
    inner_.add_held_impulses(per_body);
  }

  const std::vector<int>& nodes() const { return nodes_; }
  // The impulse on nodes()[k] since the last reset [N s].
  const std::vector<Vec3>& impulses() const { return impulse_; }
  void reset() { std::fill(impulse_.begin(), impulse_.end(), Vec3::Zero()); }

 private:
  ContactModel& inner_;
  std::vector<int> nodes_;
  std::vector<Vec3> impulse_;
  std::vector<Vec3> before_;      // f or v of the nodes before the inner model's hook
  std::vector<Vec3> last_force_;  // the model's force at the previous evaluation
  double dt_ = 0.0;               // of the step under way (0 before the first)
};

}  // namespace ccm::fields
