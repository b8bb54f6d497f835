// The rig channels from sampled simulation histories: V_i (two tracked nodes), theta_a
// (eq. 3.7), P_raw (eq. 3.8) and the sensor model (deadband, 64 Hz low-pass, sampled at the
// measurement times), against hand-computed values.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "rig_models/post/rig_channels.hpp"
#include "rig_models/signal/low_pass.hpp"
#include "tests/support/tolerance.hpp"

using namespace ccm::rig;
using ccm::test::relative_error;

TEST_CASE("rig channels: V_i is the mean of the two nodes' velocity along the track", "[rig]") {
  const std::vector<double> t = {0.0, 0.1};
  const std::vector<Eigen::Vector3d> v_a = {{1.0, 2.0, 0.0}, {0.5, 0.0, 7.0}};
  const std::vector<Eigen::Vector3d> v_b = {{3.0, 0.0, 0.0}, {-0.5, 1.0, 0.0}};
  // track along +x given unnormalised: (1 + 3)/2 = 2; (0.5 - 0.5)/2 = 0
  const TimeSeries v = impactor_velocity(t, v_a, v_b, Eigen::Vector3d(2.0, 0.0, 0.0));
  CHECK(v.value == std::vector<double>{2.0, 0.0});
  // along (1, 1, 0)/sqrt(2): ((1 + 2) + 3) / 2 / sqrt(2)
  const TimeSeries d = impactor_velocity(t, v_a, v_b, Eigen::Vector3d(1.0, 1.0, 0.0));
  CHECK(relative_error(d.value[0], 3.0 / std::sqrt(2.0)) < 1e-15);
  CHECK_THROWS_WITH(impactor_velocity(t, v_a, {v_b.data(), 1}, Eigen::Vector3d::UnitX()),
                    "impactor velocity (second node): 1 values for 2 times");
}

TEST_CASE("rig channels: theta_a = (180/pi) atan(u_y / x_z) (eq. 3.7)", "[rig]") {
  const double r = 0.25;
  const std::vector<double> t = {0.0, 0.1, 0.2};
  const std::vector<double> u_y = {0.0, r, -r * std::tan(10.0 * std::numbers::pi / 180.0)};
  const TimeSeries a = artifact_angle_deg(t, u_y, std::vector<double>(3, r));
  CHECK(a.value[0] == 0.0);
  CHECK(relative_error(a.value[1], 45.0) < 1e-15);
  CHECK(relative_error(a.value[2], -10.0) < 1e-14);
  CHECK_THROWS_WITH(artifact_angle_deg(t, u_y, std::vector<double>{r, 0.0, r}),
                    "artifact angle: distance from the centre of rotation must be > 0 (got 0 m "
                    "at 0.1 s)");
}

TEST_CASE("rig channels: the sensed pressure is deadband, low-pass, then sampled", "[rig]") {
  // Simulation output at 12.8 kHz: a 10 kPa step at t0 = 10 ms, and a 0.5 kPa bump (below a
  // 1 kPa deadband) before it. Measurement times every 1/128 s = 100 output steps.
  const double rate = 12800.0;
  const size_t n_step = 128;  // t0 = 128 / 12800 s = 10 ms
  TimeSeries raw;
  for (size_t i = 0; i < 1280; ++i) {
    raw.t.push_back(static_cast<double>(i) / rate);
    raw.value.push_back(i >= n_step ? 10.0 : (i >= 20 && i < 40 ? 0.5 : 0.0));
  }
  std::vector<double> times;
  for (int k = 0; k < 12; ++k) times.push_back(k / 128.0);
  const TimeSeries p = sensed_pressure_kpa(raw, {1.0, 64.0}, times);
  REQUIRE(p.t == times);
  // closed form of the prewarped filter's step response: y_n = 10 (1 - (-a1)^m / (1 + K)),
  // m = n - n_step output steps after the step (derived in test_low_pass.cpp)
  const double k = std::tan(std::numbers::pi * 64.0 / rate);
  const double pole = -design_low_pass(64.0, rate).a1;
  CHECK(p.value[0] == 0.0);  // the bump was below the deadband: nothing leaks through
  CHECK(p.value[1] == 0.0);
  for (size_t j = 2; j < times.size(); ++j) {  // k = 2 (15.6 ms) onwards is after the step
    const double m = std::round(times[j] * rate) - static_cast<double>(n_step);
    // 1e-9: times k/128 fall on the 12.8 kHz grid to rounding in the interpolation weight
    CHECK(relative_error(p.value[j], 10.0 * (1.0 - std::pow(pole, m) / (1.0 + k))) < 1e-9);
  }
}
