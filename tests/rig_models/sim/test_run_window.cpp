// The simulated window of a rig run (rig_models/sim/run_window.hpp): where it starts and ends,
// the gap and the initial speed, from the drive and its trial; and what a user is told when a
// window cannot be made.
#include <catch2/catch.hpp>
#include <cmath>

#include "rig_models/cases/case_file.hpp"
#include "rig_models/drive/hanging_weight_drive.hpp"
#include "rig_models/sim/run_window.hpp"

using namespace ccm::rig;

namespace {

const RigCaseTable& cases() {
  static const RigCaseTable t =
      read_case_table(std::filesystem::path(CCM_SOURCE_DIR) / "rig_models" / "cases.toml");
  return t;
}

// V_i = 2.5 t (m/s) sampled at 100 Hz to 0.6 s; contact (5 kPa) from 0.1 s at 128 Hz.
MeasuredTrial ramp_trial() {
  MeasuredTrial m;
  m.source = "RX025_t2.csv";
  for (int k = 0; k <= 60; ++k) {
    m.impactor_velocity_mps.t.push_back(0.01 * k);
    m.impactor_velocity_mps.value.push_back(2.5 * 0.01 * k);
  }
  for (int k = 0; k <= 76; ++k) {
    const double t = k / 128.0;
    m.artifact_angle_deg.t.push_back(t);
    m.artifact_angle_deg.value.push_back(0.0);
    m.pressure_kpa.t.push_back(t);
    m.pressure_kpa.value.push_back(t >= 0.1 ? 5.0 : 0.0);
  }
  return m;
}

}  // namespace

TEST_CASE("run window: open loop from the lead before contact, physical from the release",
          "[rig][window]") {
  const MeasuredTrial m = ramp_trial();
  const RigCase& c = cases().find("RX025");
  HangingWeightSettings weight;
  const double onset = 13.0 / 128.0;  // first pressure sample at or above the 1 kPa deadband
  const double lead = cases().simulation.lead.value;
  const RunWindow open =
      run_window(cases(), c, {DriveKind::open_loop, &m, {}, {}}, weight, ccm::TrackFrictionSpec{});
  CHECK(open.measured_onset.value() == Approx(onset));
  CHECK(open.start == Approx(onset - lead));
  // The local fit reproduces the ramp exactly: v(start) = 2.5 start, gap = its integral.
  CHECK(open.initial_velocity == Approx(2.5 * open.start).epsilon(1e-9));
  CHECK(open.gap == Approx(1.25 * (onset * onset - open.start * open.start)).epsilon(1e-9));
  // The end: the last time all three channels have, cut to whole output intervals.
  const double interval = cases().simulation.output_interval.value;
  CHECK(open.end <= 0.6 + 1e-12);
  CHECK(std::abs(std::remainder(open.end - open.start, interval)) < 1e-9);
  const RunWindow phys =
      run_window(cases(), c, {DriveKind::physical, &m, {}, 0.3}, weight, ccm::TrackFrictionSpec{});
  CHECK(phys.start == 0.0);
  CHECK(phys.initial_velocity == 0.0);
  CHECK(phys.gap == Approx(1.25 * onset * onset).epsilon(1e-9));
  CHECK(phys.end == Approx(0.3));
}

TEST_CASE("run window: without data the gap gives the target speed", "[rig][window]") {
  const RigCase& c = cases().find("RX050");
  HangingWeightSettings weight;  // frictionless: gap = v^2 (M + m_w) / (2 m_w g)
  const RunWindow w = run_window(cases(), c, {DriveKind::physical, nullptr, {}, {}}, weight,
                                 ccm::TrackFrictionSpec{});
  const double M = cases().rig.impactor_mass.value;
  CHECK(w.gap == Approx(0.25 * (M + 0.5) / (2 * 0.5 * 9.81)).epsilon(1e-3));
  CHECK(w.end > 2 * w.gap / 0.5);
}

TEST_CASE("run window: what cannot be run is refused with what to do", "[rig][window]") {
  const MeasuredTrial m = ramp_trial();
  const RigCase& c = cases().find("RX025");
  HangingWeightSettings weight;
  CHECK_THROWS_WITH(run_window(cases(), c, {DriveKind::open_loop, nullptr, {}, {}}, weight,
                               ccm::TrackFrictionSpec{}),
                    Catch::StartsWith("the open-loop drive follows a measured trial: give --data"));
  CHECK_THROWS_WITH(
      run_window(cases(), c, {DriveKind::physical, &m, 0.05, {}}, weight, ccm::TrackFrictionSpec{}),
      "--start: a physical run starts at the release, t = 0");
  CHECK_THROWS_WITH(
      run_window(cases(), c, {DriveKind::open_loop, &m, 0.2, {}}, weight, ccm::TrackFrictionSpec{}),
      Catch::Contains("before its contact at 0.1015625 s"));
  MeasuredTrial quiet = m;
  for (double& p : quiet.pressure_kpa.value) p = 0.5;  // below the deadband
  CHECK_THROWS_WITH(run_window(cases(), c, {DriveKind::open_loop, &quiet, {}, {}}, weight,
                               ccm::TrackFrictionSpec{}),
                    "RX025_t2.csv: no measured contact (the pressure never reaches the 1 kPa "
                    "deadband); the drive needs one");
}
