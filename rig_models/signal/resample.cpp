#include "rig_models/signal/resample.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace ccm::rig {

TimeSeries sample_at(const TimeSeries& signal, std::span<const double> times) {
  check_time_series(signal, "resample input", 1);
  const std::vector<double>& t = signal.t;
  TimeSeries out{{times.begin(), times.end()}, std::vector<double>(times.size())};
  for (size_t i = 0; i < times.size(); ++i) {
    const double ti = times[i];
    if (ti < t.front() || ti > t.back())
      throw std::invalid_argument(fmt::format(
          "resample: time {} s is outside the signal's [{}, {}] s", ti, t.front(), t.back()));
    // First sample at or after ti; interpolate on [k-1, k].
    const size_t k = static_cast<size_t>(std::lower_bound(t.begin(), t.end(), ti) - t.begin());
    if (t[k] == ti) {
      out.value[i] = signal.value[k];
      continue;
    }
    const double w = (ti - t[k - 1]) / (t[k] - t[k - 1]);
    out.value[i] = (1.0 - w) * signal.value[k - 1] + w * signal.value[k];
  }
  return out;
}

std::vector<double> times_inside(const TimeSeries& signal, std::span<const double> times) {
  std::vector<double> out;
  if (signal.t.empty()) return out;
  for (double ti : times)
    if (ti >= signal.t.front() && ti <= signal.t.back()) out.push_back(ti);
  return out;
}

}  // namespace ccm::rig
