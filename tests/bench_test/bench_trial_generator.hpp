// A generator of bench tests of the class `ccm validate` meets: a simulated history sampled as a
// data logger would record it — on its own clock (an offset from the simulation's), at its own
// rate, in its own units, with noise and a slow drift — one file per trial.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace ccm::test {

struct Curve {
  std::vector<double> t, value;  // SI, on the simulation's clock
};

// Linear interpolation of `c` at t (clamped to its ends).
inline double curve_at(const Curve& c, double t) {
  if (t <= c.t.front()) return c.value.front();
  if (t >= c.t.back()) return c.value.back();
  const auto hi =
      static_cast<std::size_t>(std::upper_bound(c.t.begin(), c.t.end(), t) - c.t.begin());
  const double w = (t - c.t[hi - 1]) / (c.t[hi] - c.t[hi - 1]);
  return (1 - w) * c.value[hi - 1] + w * c.value[hi];
}

// The rate of a curve: difference quotients at the intervals' midpoints.
inline Curve rate_of(const Curve& c) {
  Curve r;
  for (std::size_t k = 1; k < c.t.size(); ++k) {
    if (!(c.t[k] > c.t[k - 1])) continue;
    r.t.push_back(0.5 * (c.t[k] + c.t[k - 1]));
    r.value.push_back((c.value[k] - c.value[k - 1]) / (c.t[k] - c.t[k - 1]));
  }
  return r;
}

struct LoggedChannel {
  std::string column;  // header name
  Curve truth;         // SI
  double unit = 1.0;   // SI per logged unit (the file holds value / unit)
  double noise = 0.0;  // SI, standard deviation
  double drift = 0.0;  // SI, grows linearly from 0 at the first sample to this at the last
};

struct Logger {
  double rate_hz = 10000.0;
  double time_unit = 1e-3;  // s per logged time unit
  std::string time_column = "time_ms";
};

// One trial file: the logger's clock reads t + offset at simulation time t, samples on its own
// grid (multiples of 1 / rate) inside [offset, offset + span].
inline void write_trial(const std::filesystem::path& file, const Logger& logger,
                        const std::vector<LoggedChannel>& channels, double offset, double span,
                        unsigned seed) {
  constexpr int kAveraged = 16;
  std::mt19937 rng(seed);
  std::normal_distribution<double> unit_normal(0.0, 1.0);
  std::ofstream out(file);
  out << logger.time_column;
  for (const LoggedChannel& c : channels) out << "," << c.column;
  out << "\n";
  const double dt = 1.0 / logger.rate_hz;
  const auto first = static_cast<long>(std::ceil(offset / dt));
  const auto last = static_cast<long>(std::floor((offset + span) / dt));
  for (long k = first; k <= last; ++k) {
    const double clock = static_cast<double>(k) * dt;
    const double progress = static_cast<double>(k - first) / static_cast<double>(last - first);
    out << fmt::format("{:.10g}", clock / logger.time_unit);
    for (const LoggedChannel& c : channels) {
      // A logger's anti-aliasing: the truth averaged over the sample interval around the sample.
      double mean = 0.0;
      for (int j = 0; j < kAveraged; ++j)
        mean += curve_at(c.truth, clock - offset + dt * ((j + 0.5) / kAveraged - 0.5)) / kAveraged;
      const double v = mean + c.noise * unit_normal(rng) + c.drift * progress;
      out << fmt::format(",{:.10g}", v / c.unit);
    }
    out << "\n";
  }
}

}  // namespace ccm::test
