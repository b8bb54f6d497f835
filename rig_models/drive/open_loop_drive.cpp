#include "rig_models/drive/open_loop_drive.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <utility>

#include "rig_models/signal/resample.hpp"

namespace ccm::rig {

bool pressure_nonzero_at(const TimeSeries& pressure, double t) {
  const std::vector<double>& ts = pressure.t;
  if (ts.empty() || t < ts.front() || t > ts.back()) return false;
  const size_t k = static_cast<size_t>(std::lower_bound(ts.begin(), ts.end(), t) - ts.begin());
  if (pressure.value[k] > 0.0) return true;
  return ts[k] != t && k > 0 && pressure.value[k - 1] > 0.0;
}

namespace {

TimeSeries part(const TimeSeries& s, size_t from, size_t to) {
  return {{s.t.begin() + static_cast<long>(from), s.t.begin() + static_cast<long>(to)},
          {s.value.begin() + static_cast<long>(from), s.value.begin() + static_cast<long>(to)}};
}

void append(TimeSeries& to, const TimeSeries& from) {
  to.t.insert(to.t.end(), from.t.begin(), from.t.end());
  to.value.insert(to.value.end(), from.value.begin(), from.value.end());
}

}  // namespace

LocalFit velocity_fit(const MeasuredTrial& trial, double half_window) {
  const TimeSeries& v = trial.impactor_velocity_mps;
  const auto& p = trial.pressure_kpa;
  // The contact began after the last zero reading before the first non-zero one.
  double t_contact = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < p.t.size(); ++k)
    if (p.value[k] > 0.0) {
      t_contact = k > 0 ? p.t[k - 1] : p.t[k];
      break;
    }
  const size_t split =
      static_cast<size_t>(std::upper_bound(v.t.begin(), v.t.end(), t_contact) - v.t.begin());
  if (split < 4 || v.t.size() - split < 4) return local_quadratic_fit(v, half_window);
  LocalFit before = local_quadratic_fit(part(v, 0, split), half_window);
  const LocalFit after = local_quadratic_fit(part(v, split, v.t.size()), half_window);
  append(before.value, after.value);
  append(before.derivative, after.derivative);
  return before;
}

OpenLoopDrive open_loop_drive(const MeasuredTrial& trial, double impactor_mass,
                              double half_window) {
  if (!(impactor_mass > 0.0))
    throw std::invalid_argument(
        fmt::format("open-loop drive: impactor mass must be > 0 (got {})", impactor_mass));
  const LocalFit fit = velocity_fit(trial, half_window);
  OpenLoopDrive d;
  d.smoothed_velocity = fit.value;
  d.force_n = fit.derivative;
  for (size_t k = 0; k < d.force_n.t.size(); ++k) {
    double& F = d.force_n.value[k];
    F *= impactor_mass;  // F_in = M_i dV_i/dt   (3.3.2)
    if (F < 0.0 && pressure_nonzero_at(trial.pressure_kpa, d.force_n.t[k])) {
      F = 0.0;  // during contact only the weight's pull, never a brake   (3.3.2)
      ++d.masked_samples;
    }
  }
  return d;
}

TimeTable OpenLoopDrive::force_table() const {
  std::vector<std::pair<double, double>> points;
  for (size_t k = 0; k < force_n.t.size(); ++k) points.emplace_back(force_n.t[k], force_n.value[k]);
  return TimeTable(std::move(points));
}

double travel(const TimeSeries& velocity, double t0, double t1) {
  check_time_series(velocity, "travel", 2);
  if (!(t0 <= t1)) throw std::invalid_argument("travel: t0 must not be after t1");
  std::vector<double> times{t0};
  for (double t : velocity.t)
    if (t > t0 && t < t1) times.push_back(t);
  times.push_back(t1);
  const TimeSeries v = sample_at(velocity, times);
  double distance = 0.0;
  for (size_t k = 1; k < times.size(); ++k)
    distance += 0.5 * (v.value[k] + v.value[k - 1]) * (times[k] - times[k - 1]);
  return distance;
}

}  // namespace ccm::rig
