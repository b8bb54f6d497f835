#include "correlate/cfc_filter.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ccm::correlate {

namespace {

// SAE J211-1's design factor: the two-pole design frequency over the class (CFC.1).
constexpr double kDesignFactor = 2.0775;

// One pass of CFC.3 over `x`, in place, from a steady state at x[0] (the DC gain is 1).
void filter_pass(std::vector<double>& x, const CfcCoefficients& c) {
  double x1 = x.front(), x2 = x.front(), y1 = x.front(), y2 = x.front();
  for (double& value : x) {
    const double y = c.a0 * value + c.a1 * x1 + c.a2 * x2 + c.b1 * y1 + c.b2 * y2;
    x2 = x1;
    x1 = value;
    y2 = y1;
    y1 = y;
    value = y;
  }
}

// The record with `pad` samples reflected oddly about each end value: x_{-k} = 2 x_0 - x_k.
std::vector<double> padded(std::span<const double> samples, std::size_t pad) {
  const std::size_t n = samples.size();
  std::vector<double> out;
  out.reserve(n + 2 * pad);
  for (std::size_t k = pad; k >= 1; --k) out.push_back(2.0 * samples[0] - samples[k]);
  out.insert(out.end(), samples.begin(), samples.end());
  for (std::size_t k = 1; k <= pad; ++k) out.push_back(2.0 * samples[n - 1] - samples[n - 1 - k]);
  return out;
}

}  // namespace

CfcCoefficients design_cfc(double cfc, double sample_interval) {
  if (!(cfc > 0.0) || !std::isfinite(cfc))
    throw std::invalid_argument(fmt::format("CFC class {} must be a positive number", cfc));
  if (!(sample_interval > 0.0) || !std::isfinite(sample_interval))
    throw std::invalid_argument(
        fmt::format("sample interval {} s must be a positive number", sample_interval));
  const double design_hz = kDesignFactor * cfc;
  const double nyquist_hz = 0.5 / sample_interval;
  if (design_hz >= nyquist_hz)
    throw std::invalid_argument(fmt::format(
        "CFC {} needs samples faster than {:.6g} Hz (its design frequency {:.6g} Hz must lie below "
        "the Nyquist frequency); these are at {:.6g} Hz",
        cfc, 2.0 * design_hz, design_hz, 1.0 / sample_interval));
  const double wd = 2.0 * std::numbers::pi * design_hz;
  const double wa = std::tan(wd * sample_interval / 2.0);
  const double root2 = std::numbers::sqrt2;
  const double d = 1.0 + root2 * wa + wa * wa;
  CfcCoefficients c;
  c.a0 = wa * wa / d;
  c.a1 = 2.0 * c.a0;
  c.a2 = c.a0;
  c.b1 = -2.0 * (wa * wa - 1.0) / d;
  c.b2 = (-1.0 + root2 * wa - wa * wa) / d;
  return c;
}

std::vector<double> cfc_filter(std::span<const double> samples, double cfc,
                               double sample_interval) {
  const CfcCoefficients c = design_cfc(cfc, sample_interval);
  if (samples.size() < 3)
    throw std::invalid_argument(
        fmt::format("a CFC filter needs at least 3 samples; the record has {}", samples.size()));
  for (std::size_t i = 0; i < samples.size(); ++i)
    if (!std::isfinite(samples[i]))
      throw std::invalid_argument(fmt::format("sample {} is not a finite number", i));
  // Two periods of the class frequency on each side, as the filter's memory is about that long.
  const auto periods = static_cast<std::size_t>(std::ceil(2.0 / (cfc * sample_interval))) + 10;
  const std::size_t pad = std::min(samples.size() - 1, periods);
  std::vector<double> x = padded(samples, pad);
  filter_pass(x, c);
  std::reverse(x.begin(), x.end());
  filter_pass(x, c);
  std::reverse(x.begin(), x.end());
  return {x.begin() + static_cast<std::ptrdiff_t>(pad),
          x.begin() + static_cast<std::ptrdiff_t>(pad + samples.size())};
}

}  // namespace ccm::correlate
