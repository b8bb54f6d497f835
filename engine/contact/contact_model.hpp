// The hook through which a contact model acts on an explicit step (thesis 2.5.2): after the
// internal forces are evaluated and before the velocity is corrected. A scene without contact
// passes no model at all and pays nothing.
#pragma once

#include <limits>
#include <string_view>

#include "engine/solver/state.hpp"

namespace ccm {

class ContactModel {
 public:
  virtual ~ContactModel() = default;
  virtual std::string_view name() const = 0;
  // Corrects positions x and the predicted velocities v (and may add to a) of the step of
  // size dt that has just been predicted and evaluated.
  virtual void correct(State& state, double dt) = 0;
  // The largest step the contact model allows from this state.
  virtual double stable_dt_limit(const State& /*state*/) const {
    return std::numeric_limits<double>::infinity();
  }
  // Work the contact model has done on the bodies so far, for the energy balance.
  virtual double work() const { return 0.0; }
};

}  // namespace ccm
