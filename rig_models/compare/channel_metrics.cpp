#include "rig_models/compare/channel_metrics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rig_models/signal/resample.hpp"

namespace ccm::rig {
namespace {

// The measurement restricted to the simulated span, and the simulation sampled on it.
struct Aligned {
  TimeSeries measured;
  TimeSeries simulated;
};

Aligned align(const TimeSeries& measured, const TimeSeries& simulated) {
  check_time_series(measured, "measured channel");
  check_time_series(simulated, "simulated channel");
  Aligned a;
  for (size_t k = 0; k < measured.t.size(); ++k)
    if (measured.t[k] >= simulated.t.front() && measured.t[k] <= simulated.t.back()) {
      a.measured.t.push_back(measured.t[k]);
      a.measured.value.push_back(measured.value[k]);
    }
  if (a.measured.t.size() < 2)
    throw std::invalid_argument(
        fmt::format("compare: only {} measurement samples lie in the simulated span [{}, {}] s",
                    a.measured.t.size(), simulated.t.front(), simulated.t.back()));
  a.simulated = sample_at(simulated, a.measured.t);
  return a;
}

size_t peak_index(const std::vector<double>& v) {
  const auto it = std::max_element(v.begin(), v.end(),
                                   [](double a, double b) { return std::abs(a) < std::abs(b); });
  return static_cast<size_t>(it - v.begin());
}

}  // namespace

ChannelComparison compare_channel(const TimeSeries& measured, const TimeSeries& simulated) {
  const Aligned a = align(measured, simulated);
  const std::vector<double>& m = a.measured.value;
  const std::vector<double>& s = a.simulated.value;
  ChannelComparison c;
  c.n_samples = m.size();
  double sum_sq = 0.0;
  for (size_t k = 0; k < m.size(); ++k) sum_sq += (s[k] - m[k]) * (s[k] - m[k]);
  c.rmse = std::sqrt(sum_sq / static_cast<double>(m.size()));
  const auto [lo, hi] = std::minmax_element(m.begin(), m.end());
  if (*hi > *lo) c.nrmse = c.rmse / (*hi - *lo);
  const size_t pm = peak_index(m);
  const size_t ps = peak_index(s);
  c.peak_measured = m[pm];
  c.peak_simulated = s[ps];
  c.peak_error = s[ps] - m[pm];
  c.peak_time_error = a.measured.t[ps] - a.measured.t[pm];
  return c;
}

std::optional<ChannelComparison> compare_channel_within(const TimeSeries& measured,
                                                        const TimeSeries& simulated, double t0,
                                                        double t1) {
  check_time_series(simulated, "simulated channel");
  TimeSeries inside;
  for (size_t k = 0; k < measured.t.size(); ++k) {
    const double t = measured.t[k];
    if (t >= t0 && t <= t1 && t >= simulated.t.front() && t <= simulated.t.back()) {
      inside.t.push_back(t);
      inside.value.push_back(measured.value[k]);
    }
  }
  if (inside.t.size() < 2) return std::nullopt;
  return compare_channel(inside, simulated);
}

std::optional<ContactWindow> first_contact(const TimeSeries& pressure, double threshold) {
  if (!(threshold > 0.0))
    throw std::invalid_argument(fmt::format("contact threshold must be > 0 (got {})", threshold));
  check_time_series(pressure, "pressure");
  const std::vector<double>& p = pressure.value;
  const auto on = std::find_if(p.begin(), p.end(), [&](double v) { return v >= threshold; });
  if (on == p.end()) return std::nullopt;
  const auto off = std::find_if(on, p.end(), [&](double v) { return v < threshold; });
  const size_t i_on = static_cast<size_t>(on - p.begin());
  ContactWindow w;
  w.onset = pressure.t[i_on];
  w.released = off != p.end();
  const size_t i_off = w.released ? static_cast<size_t>(off - p.begin()) : p.size() - 1;
  w.duration = pressure.t[i_off] - w.onset;
  return w;
}

ContactComparison compare_contact(const TimeSeries& measured_pressure,
                                  const TimeSeries& simulated_pressure, double threshold) {
  const Aligned a = align(measured_pressure, simulated_pressure);
  ContactComparison c;
  c.measured = first_contact(a.measured, threshold);
  c.simulated = first_contact(a.simulated, threshold);
  if (c.measured && c.simulated) {
    c.onset_error = c.simulated->onset - c.measured->onset;
    c.duration_error = c.simulated->duration - c.measured->duration;
  }
  return c;
}

}  // namespace ccm::rig
