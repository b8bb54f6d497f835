// The open-loop drive (thesis 3.3.2): F_in = M_i dV_i/dt of the measured velocity, negative
// values set to zero while the measured pressure is non-zero; and the distance a velocity covers.
#include <catch2/catch.hpp>

#include "rig_models/drive/open_loop_drive.hpp"

using namespace ccm::rig;

namespace {

// V_i accelerates at 3 m/s^2 to 0.3 s, then drops linearly to 0 by 0.35 s (the contact), then
// rises again at 1 m/s^2; the pressure is 5 kPa from 0.3 to 0.36 s (128 Hz).
MeasuredTrial synthetic_trial() {
  MeasuredTrial m;
  for (int k = 0; k <= 50; ++k) {
    const double t = 0.01 * k;
    const double v = t <= 0.3 ? 3.0 * t : t <= 0.35 ? 0.9 * (0.35 - t) / 0.05 : 1.0 * (t - 0.35);
    m.impactor_velocity_mps.t.push_back(t);
    m.impactor_velocity_mps.value.push_back(v);
  }
  for (int k = 0; k <= 64; ++k) {
    const double t = k / 128.0;
    m.pressure_kpa.t.push_back(t);
    m.pressure_kpa.value.push_back(t >= 0.3 && t <= 0.36 ? 5.0 : 0.0);
  }
  return m;
}

}  // namespace

TEST_CASE("open-loop drive: M dV/dt before contact, no braking while the pressure is on",
          "[rig][drive]") {
  const MeasuredTrial m = synthetic_trial();
  const double M = 1.2;
  const OpenLoopDrive d = open_loop_drive(m, M, 0.015);  // 3-point windows: the ramp is exact
  const auto F = [&](double t) {
    for (size_t k = 0; k < d.force_n.t.size(); ++k)
      if (std::abs(d.force_n.t[k] - t) < 1e-12) return d.force_n.value[k];
    FAIL("no sample at " << t);
    return 0.0;
  };
  CHECK(F(0.1) == Approx(M * 3.0).epsilon(1e-9));  // accelerating: F = M a
  CHECK(F(0.2) == Approx(M * 3.0).epsilon(1e-9));
  CHECK(F(0.33) == 0.0);  // decelerating during contact: set to 0 (3.3.2)
  CHECK(F(0.34) == 0.0);
  CHECK(F(0.45) == Approx(M * 1.0).epsilon(1e-9));  // after: the fit's slope, no contact
  CHECK(d.masked_samples >= 3);
  // Outside contact a deceleration is kept (the open loop follows the measurement there).
  MeasuredTrial no_pressure = m;
  for (double& p : no_pressure.pressure_kpa.value) p = 0.0;
  const OpenLoopDrive free = open_loop_drive(no_pressure, M, 0.015);
  CHECK(free.masked_samples == 0);
  CHECK(free.force_table()(0.33) == Approx(-M * 18.0).epsilon(1e-9));
}

TEST_CASE("pressure non-zero at a time: either neighbouring sample", "[rig][drive]") {
  const TimeSeries p{{0.0, 0.01, 0.02, 0.03}, {0.0, 0.0, 2.0, 0.0}};
  CHECK(!pressure_nonzero_at(p, 0.005));
  CHECK(pressure_nonzero_at(p, 0.015));
  CHECK(pressure_nonzero_at(p, 0.02));
  CHECK(pressure_nonzero_at(p, 0.025));
  CHECK(!pressure_nonzero_at(p, 0.03));
  CHECK(!pressure_nonzero_at(p, 0.5));
}

TEST_CASE("travel: trapezoids between samples, interpolated ends", "[rig][drive]") {
  const TimeSeries v{{0.0, 0.1, 0.2}, {0.0, 1.0, 1.0}};
  CHECK(travel(v, 0.0, 0.2) == Approx(0.05 + 0.1));
  CHECK(travel(v, 0.05, 0.15) == Approx(0.5 * (0.5 + 1.0) * 0.05 + 0.05));
  CHECK_THROWS(travel(v, 0.1, 0.3));
}
