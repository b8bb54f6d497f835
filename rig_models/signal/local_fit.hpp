// A smoothed signal and its derivative by local least squares (Savitzky-Golay on arbitrary
// sample times): at each sample t_k, the quadratic p(t) = c0 + c1 (t - t_k) + c2 (t - t_k)^2
// fitted to every sample within `half_window` of t_k gives the value c0 and the derivative c1;
// where the window holds fewer than four samples (near the ends) it takes the nearest ones.
// Used for the open-loop drive's dV_i/dt (thesis 3.3.2: "differentiating the tracked impactor
// velocity"), where a plain difference of 100 Hz motion-capture velocities would amplify the
// position noise.
#pragma once

#include "rig_models/signal/time_series.hpp"

namespace ccm::rig {

struct LocalFit {
  TimeSeries value;       // c0 at every sample
  TimeSeries derivative;  // c1 at every sample, per second
};

// Throws std::invalid_argument unless half_window > 0 and the signal has at least four samples
// (a quadratic needs three; four so that one noisy sample is not interpolated).
LocalFit local_quadratic_fit(const TimeSeries& signal, double half_window);

}  // namespace ccm::rig
