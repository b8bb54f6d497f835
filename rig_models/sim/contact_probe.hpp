// The sensor's contact force as the thesis measured it in SUMMIT (3.3.3): "whenever the DCR
// method updated the nodal velocities, reflecting a node had been pushed back to enforce
// contact, this velocity was differentiated across the model time step and multiplied by that
// node's lumped nodal mass ... projected along the axis of motion of the impactor" and summed
// over the sensor surface Gamma_s:
//   F_c = sum_{j in Gamma_s} m_j (v_j,after - v_j,before) . d / dt          (docs/equations.md
//   "Contact force and sensor pressure")
// A contact model decorator: it forwards every hook of ContactModel (all nine, the figures the
// monitor checks included: a dropped injected_energy would switch off the contact-energy check
// in every rig run) to the model it wraps and, around its correction, reads the velocities of
// the sensor's nodes. It keeps the running impulse sum_steps F_c dt, so that a sampler can
// report the mean force over each output interval (a step-by-step F_c aliases at any output
// rate below the step rate). The wrapped model is not touched: no accessor into the DCR is
// needed.
#pragma once

#include <vector>

#include "engine/contact/contact_model.hpp"

namespace ccm::rig {

class ContactProbe : public ContactModel {
 public:
  // `inner` is not owned and must outlive the probe.
  ContactProbe(ContactModel& inner, std::vector<int> sensor_nodes, const Vec3& axis);

  void begin_step(const State& s, double dt) override { inner_.begin_step(s, dt); }
  void add_forces(State& s) override { inner_.add_forces(s); }
  void correct(State& s, double dt) override;
  // The inner model's ledger (work, injected energy, failure) becomes the probe's: the monitor's
  // checks read it.
  void end_step(const State& s, double dt) override {
    inner_.end_step(s, dt);
    ledger_ = inner_.ledger();
  }
  ContactStepBound step_bound(const State& s) const override { return inner_.step_bound(s); }

  // sum over the steps so far of F_c dt [N s], along the axis.
  double impulse() const { return impulse_; }

 private:
  ContactModel& inner_;
  std::vector<int> nodes_;
  Vec3 axis_;
  std::vector<Vec3> v_before_;
  double impulse_ = 0.0;
};

}  // namespace ccm::rig
