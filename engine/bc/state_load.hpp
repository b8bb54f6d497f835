// An external force that depends on the state: a mechanism outside the mesh acting on some of
// its nodes (a weight on a string over a pulley, the friction of a track). The integrator adds
// it at every evaluation (step 2 of the Predict-Evaluate-Correct order) at x_{n+1} and the
// predicted velocities v* = v_{n+1/2}, and lets it advance its own state after each step.
#pragma once

#include <span>
#include <string_view>

#include "engine/core/state.hpp"

namespace ccm {

class StateLoad {
 public:
  virtual ~StateLoad() = default;
  virtual std::string_view name() const = 0;

  // Adds the load's nodal forces at the state s (time s.t) into f [N].
  virtual void add_forces(const State& s, std::span<Vec3> f) = 0;
  // Called after the velocity correction of a step of size dt; s.v holds v_{n+1}.
  virtual void end_step(const State& /*s*/, double /*dt*/) {}
  // Work done by the load on the bodies so far [J], for the energy balance.
  virtual double work() const = 0;
};

}  // namespace ccm
