// First-order Butterworth low-pass, digital by the bilinear transform with the cutoff
// prewarped (thesis 3.3.3: 64 Hz on the simulated pressure, Fig. 3-22).
//
//   analog   H(s) = 1 / (1 + s / w_c)
//   digital  H(z) = K (1 + z^-1) / ((1 + K) + (K - 1) z^-1),   K = tan(pi f_c / f_s)
//   gain     |H(e^{jw})| = 1 / sqrt(1 + (tan(w / 2) / K)^2),    w = 2 pi f / f_s
//
// so the gain is exactly 1/sqrt(2) (-3.01 dB) at f_c for every f_s > 2 f_c. At f_c = f_s / 2
// (a 64 Hz cutoff at the sensor's own 128 Hz) K is infinite and H(z) = 1: the filter does
// nothing, so that design is refused — it is meant for the simulation's output rate.
#pragma once

#include "rig_models/signal/time_series.hpp"

namespace ccm::rig {

struct FirstOrderLowPass {
  double b0 = 1.0;  // y_n = b0 x_n + b1 x_{n-1} - a1 y_{n-1}
  double b1 = 0.0;
  double a1 = 0.0;
};

// The prewarped bilinear design; throws std::invalid_argument unless 0 < f_c < f_s / 2.
FirstOrderLowPass design_low_pass(double cutoff_hz, double sample_rate_hz);

// The gain |H| of `filter` at `frequency_hz` for the sample rate it was designed for.
double low_pass_gain(const FirstOrderLowPass& filter, double frequency_hz, double sample_rate_hz);

// Filters a uniformly sampled signal (relative spread of the steps at most 1e-6, else
// std::invalid_argument) starting from the steady state of its first value, so a constant
// passes unchanged.
TimeSeries apply_low_pass(const TimeSeries& signal, double cutoff_hz);

}  // namespace ccm::rig
