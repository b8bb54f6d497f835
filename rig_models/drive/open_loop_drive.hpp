// The thesis's open-loop drive (3.3.2): "the input force provided to the impactor ... was
// calculated through differentiating the tracked impactor velocity, V_i, over time and computing
// the input force through the known mass of the impactor ... whenever the experimental pressure,
// P, was non-zero and the differentiated input force was negative, the input force was instead
// forced to zero" (docs/equations.md "Rig: open-loop drive"):
//   F_in(t_k) = M_i dV_i/dt (t_k)   (V_i smoothed by a local quadratic fit, local_fit.hpp,
//                                     that does not reach across the first measured contact)
//   F_in(t_k) = 0 where F_in(t_k) < 0 and the measured P is non-zero at t_k
// at the velocity samples t_k, linear in between; it acts on the impactor's drive surface (the
// bracket, Fig. 3-16) along the track.
#pragma once

#include "engine/core/time_table.hpp"
#include "rig_models/measurement/measured_trial.hpp"
#include "rig_models/signal/local_fit.hpp"

namespace ccm::rig {

struct OpenLoopDrive {
  TimeSeries force_n;            // F_in at the velocity samples [N]
  TimeSeries smoothed_velocity;  // V_i of the local fit [m/s]
  int masked_samples = 0;        // samples set to 0 by the pressure rule

  TimeTable force_table() const;  // F_in(t), constant outside the samples
};

// Throws std::invalid_argument when the mass is not positive or the velocity cannot be
// smoothed (too few samples in a window, see local_fit.hpp).
OpenLoopDrive open_loop_drive(const MeasuredTrial& trial, double impactor_mass, double half_window);

// The measured V_i smoothed by local quadratic fits (local_fit.hpp) on either side of the
// contact's start, separately (the start: the last zero pressure reading before the first
// non-zero one; velocity samples up to it are "before"): a window straddling the contact would read
// the contact's deceleration as a brake before it (measured: on RX025 trial 2 the +-20 ms fit
// turned the last 20 ms before contact into a deceleration of ~2 m/s^2, the measured V_i rising
// at 1.6 m/s^2 there). A side with fewer than four samples is fitted with the other.
LocalFit velocity_fit(const MeasuredTrial& trial, double half_window);

// Whether the measured pressure is non-zero at t: a sample at or next to t (before or after)
// reads above zero. Outside the pressure's span: false.
bool pressure_nonzero_at(const TimeSeries& pressure, double t);

// The distance travelled from t0 to t1 by the velocity, trapezoidal between its samples
// (linear interpolation at the ends). Throws std::invalid_argument outside its span.
double travel(const TimeSeries& velocity, double t0, double t1);

}  // namespace ccm::rig
