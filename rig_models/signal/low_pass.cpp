#include "rig_models/signal/low_pass.hpp"

#include <fmt/format.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

namespace ccm::rig {
namespace {

// The signal's sample rate; throws unless the steps are uniform to 1e-6 relative.
double uniform_sample_rate(const TimeSeries& s) {
  const size_t n = s.t.size();
  const double dt = (s.t[n - 1] - s.t[0]) / static_cast<double>(n - 1);
  for (size_t i = 1; i < n; ++i) {
    const double step = s.t[i] - s.t[i - 1];
    if (std::abs(step - dt) > 1e-6 * dt)
      throw std::invalid_argument(fmt::format(
          "low-pass: the signal is not uniformly sampled (step {} s at sample {}, mean {} s)", step,
          i, dt));
  }
  return 1.0 / dt;
}

}  // namespace

FirstOrderLowPass design_low_pass(double cutoff_hz, double sample_rate_hz) {
  if (!(cutoff_hz > 0.0) || !(sample_rate_hz > 2.0 * cutoff_hz) || !std::isfinite(sample_rate_hz))
    throw std::invalid_argument(fmt::format(
        "low-pass: cutoff {} Hz needs a sample rate above twice it (got {} Hz); filter at the "
        "simulation's output rate, not at the sensor's",
        cutoff_hz, sample_rate_hz));
  const double k = std::tan(std::numbers::pi * cutoff_hz / sample_rate_hz);  // prewarped
  return {k / (1.0 + k), k / (1.0 + k), (k - 1.0) / (k + 1.0)};
}

double low_pass_gain(const FirstOrderLowPass& filter, double frequency_hz, double sample_rate_hz) {
  const double w = 2.0 * std::numbers::pi * frequency_hz / sample_rate_hz;
  const std::complex<double> z_inv = std::polar(1.0, -w);
  return std::abs((filter.b0 + filter.b1 * z_inv) / (1.0 + filter.a1 * z_inv));
}

TimeSeries apply_low_pass(const TimeSeries& signal, double cutoff_hz) {
  check_time_series(signal, "low-pass input", 2);
  const FirstOrderLowPass f = design_low_pass(cutoff_hz, uniform_sample_rate(signal));
  TimeSeries out{signal.t, std::vector<double>(signal.value.size())};
  double x_prev = signal.value[0];
  double y_prev = signal.value[0];  // steady state: y = x for a constant x
  for (size_t i = 0; i < signal.value.size(); ++i) {
    const double x = signal.value[i];
    out.value[i] = f.b0 * x + f.b1 * x_prev - f.a1 * y_prev;
    x_prev = x;
    y_prev = out.value[i];
  }
  return out;
}

}  // namespace ccm::rig
