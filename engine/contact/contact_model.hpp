// The hook through which a contact model acts on an explicit step (thesis 2.5.2). A scene
// without contact passes no model at all and pays nothing: no search, no surface data.
//
// Order within a step (engine/solver/explicit_integrator.hpp):
//   begin_step (x_n, v_n known)  ->  predict  ->  add_forces (into f, before a = M^-1 f)
//   ->  accelerations  ->  correct (x_{n+1}, v*)  ->  boundary conditions  ->  v correction
//   ->  end_step.
#pragma once

#include <limits>
#include <string>
#include <string_view>

#include "engine/core/state.hpp"

namespace ccm {

class ContactModel {
 public:
  virtual ~ContactModel() = default;
  virtual std::string_view name() const = 0;

  // Called with the state at t_n before the predictor of a step of size dt.
  virtual void begin_step(const State& /*state*/, double /*dt*/) {}
  // Penalty-type models add their forces on the nodes into state.f (at x_{n+1}).
  virtual void add_forces(State& /*state*/) {}
  // Constraint-type models correct x_{n+1} and the predicted velocities v* (thesis 2.5.2).
  virtual void correct(State& /*state*/, double /*dt*/) {}
  // Called after the velocity correction; v holds v_{n+1}.
  virtual void end_step(const State& /*state*/, double /*dt*/) {}

  // The largest step the contact model allows from this state.
  virtual double stable_dt_limit(const State& /*state*/) const {
    return std::numeric_limits<double>::infinity();
  }
  // Work done on the deformable bodies by the contact so far [J], for the energy balance.
  virtual double work() const { return 0.0; }
  // The part of work() the model's physics does not allow [J], >= 0: a model whose contacts can
  // only dissipate (all bodies in the model, inelastic or elastic constraints) reports its net
  // positive work, energy its push-back injected. The monitor ends a run when it exceeds the
  // energy tolerance. A model that exchanges energy with something outside the model (a rigid
  // sphere's kinetic energy) reports 0.
  virtual double injected_energy() const { return 0.0; }
  // Non-empty when the contact has failed in the last step (the reason, for the verdict): the
  // run must then end unstable. Checked by the integrator after every step.
  virtual std::string failure() const { return {}; }
};

}  // namespace ccm
