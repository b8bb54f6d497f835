#include "rig_models/post/rig_channels.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "rig_models/signal/deadband.hpp"
#include "rig_models/signal/low_pass.hpp"
#include "rig_models/signal/resample.hpp"

namespace ccm::rig {
namespace {

void require_same_size(size_t n_t, size_t n, const char* what) {
  if (n != n_t)
    throw std::invalid_argument(fmt::format("{}: {} values for {} times", what, n, n_t));
}

}  // namespace

TimeSeries impactor_velocity(std::span<const double> t, std::span<const Eigen::Vector3d> v_a,
                             std::span<const Eigen::Vector3d> v_b,
                             const Eigen::Vector3d& track_direction) {
  require_same_size(t.size(), v_a.size(), "impactor velocity (first node)");
  require_same_size(t.size(), v_b.size(), "impactor velocity (second node)");
  const double norm = track_direction.norm();
  if (!(norm > 0.0) || !std::isfinite(norm))
    throw std::invalid_argument(
        "impactor velocity: the track direction must be a finite, "
        "non-zero vector");
  const Eigen::Vector3d d = track_direction / norm;
  TimeSeries out{{t.begin(), t.end()}, std::vector<double>(t.size())};
  for (size_t i = 0; i < t.size(); ++i) out.value[i] = 0.5 * (v_a[i] + v_b[i]).dot(d);
  check_time_series(out, "impactor velocity");
  return out;
}

TimeSeries artifact_angle_deg(std::span<const double> t, std::span<const double> u_y,
                              std::span<const double> x_z) {
  require_same_size(t.size(), u_y.size(), "artifact angle (u_y)");
  require_same_size(t.size(), x_z.size(), "artifact angle (x_z)");
  TimeSeries out{{t.begin(), t.end()}, std::vector<double>(t.size())};
  for (size_t i = 0; i < t.size(); ++i) {
    if (!(x_z[i] > 0.0))
      throw std::invalid_argument(fmt::format(
          "artifact angle: distance from the centre of rotation must be > 0 (got {} m at {} s)",
          x_z[i], t[i]));
    out.value[i] = 180.0 / std::numbers::pi * std::atan(u_y[i] / x_z[i]);  // (3.7)
  }
  check_time_series(out, "artifact angle");
  return out;
}

TimeSeries sensed_pressure_kpa(const TimeSeries& raw_kpa, const PressureSensor& sensor,
                               std::span<const double> measurement_times) {
  const TimeSeries filtered =
      apply_low_pass(apply_deadband(raw_kpa, sensor.deadband_kpa), sensor.cutoff_hz);
  return sample_at(filtered, measurement_times);
}

}  // namespace ccm::rig
