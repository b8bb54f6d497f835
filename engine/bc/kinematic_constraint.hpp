// A constraint on the motion of some nodes, applied by the integrator after the contact
// correction, beside the fixed nodes (step 4 of the Predict-Evaluate-Correct order, thesis
// 2.5.2 and 3.3.2: the free artifact's rotational boundary condition "is enforced as an
// additional Corrector step ... after both structural mechanics and contact mechanics").
//
// On entry of apply() the state holds x_{n+1} (predicted, contact-corrected), the predicted
// velocities v* and the accelerations a_{n+1}; the constraint corrects x_{n+1} and v* so that
// the end-of-step velocity v_{n+1} = v* + dt/2 a_{n+1} satisfies it. Whatever its reactions do
// (friction dissipates) it books as work, so the energy balance still closes.
#pragma once

#include <string_view>
#include <vector>

#include "engine/core/state.hpp"

namespace ccm {

class KinematicConstraint {
 public:
  virtual ~KinematicConstraint() = default;
  virtual std::string_view name() const = 0;
  // The nodes it reads and writes (a partitioned run gathers them onto every rank,
  // engine/distributed/replicated_constraint.hpp).
  virtual const std::vector<int>& nodes() const = 0;

  // Called once with the initial state (after the first evaluation): masses are known; the
  // constraint may correct the initial velocities and accelerations of its nodes.
  virtual void initialise(State& /*state*/) {}
  // Step 4 of a step of size dt (see above).
  virtual void apply(State& state, double dt) = 0;
  // Work done on the bodies by the constraint's reactions so far [J].
  virtual double work() const { return 0.0; }
};

}  // namespace ccm
