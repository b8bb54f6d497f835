// Per-channel comparison metrics and contact onset/duration against hand-computed values.
#include <catch2/catch.hpp>
#include <cmath>
#include <stdexcept>

#include "rig_models/compare/channel_metrics.hpp"
#include "tests/support/tolerance.hpp"

using namespace ccm::rig;
using ccm::test::relative_error;

TEST_CASE("channel metrics: RMSE, nRMSE, peak and peak time on the measured timestamps", "[rig]") {
  const TimeSeries measured{{0.0, 1.0, 2.0, 3.0}, {0.0, 1.0, 3.0, 1.0}};
  // simulation on a finer grid, linear between its samples: at t = 0,1,2,3 it is 0,2,2,1
  const TimeSeries simulated{{0.0, 0.5, 1.0, 2.0, 2.5, 3.0}, {0.0, 7.0, 2.0, 2.0, -5.0, 1.0}};
  const ChannelComparison c = compare_channel(measured, simulated);
  CHECK(c.n_samples == 4);
  // differences 0, 1, -1, 0: RMSE = sqrt(2/4); range of the measurement 3
  CHECK(relative_error(c.rmse, std::sqrt(0.5)) < 1e-15);
  REQUIRE(c.nrmse);
  CHECK(relative_error(*c.nrmse, std::sqrt(0.5) / 3.0) < 1e-15);
  // peaks as the sensor would see them: 3 at t = 2 measured, 2 first at t = 1 simulated (the
  // 7 and -5 between samples are not seen)
  CHECK(c.peak_measured == 3.0);
  CHECK(c.peak_simulated == 2.0);
  CHECK(c.peak_error == -1.0);
  CHECK(c.peak_time_error == -1.0);
}

TEST_CASE("channel metrics: only the overlap is compared, a negative peak keeps its sign",
          "[rig]") {
  const TimeSeries measured{{0.0, 1.0, 2.0, 3.0}, {0.0, -4.0, 1.0, 2.0}};
  const TimeSeries simulated{{0.5, 3.0}, {-1.0, 1.5}};  // at t = 1, 2, 3: -0.5, 0.5, 1.5
  const ChannelComparison c = compare_channel(measured, simulated);
  CHECK(c.n_samples == 3);
  // differences 3.5, -0.5, -0.5: RMSE = sqrt((12.25 + 0.25 + 0.25) / 3); range 6
  CHECK(relative_error(c.rmse, std::sqrt(12.75 / 3.0)) < 1e-15);
  CHECK(relative_error(*c.nrmse, std::sqrt(12.75 / 3.0) / 6.0) < 1e-15);
  CHECK(c.peak_measured == -4.0);
  CHECK(c.peak_simulated == 1.5);
  CHECK(c.peak_error == 5.5);
  CHECK(c.peak_time_error == 2.0);
  // a constant measurement has no range: no nRMSE
  CHECK_FALSE(compare_channel({{0.0, 1.0}, {2.0, 2.0}}, {{0.0, 1.0}, {2.0, 3.0}}).nrmse);
  CHECK_THROWS_WITH(compare_channel(measured, {{2.5, 4.0}, {0.0, 0.0}}),
                    "compare: only 1 measurement samples lie in the simulated span [2.5, 4] s");
}

TEST_CASE("contact: onset at the first sample at or above the threshold, duration to release",
          "[rig]") {
  const TimeSeries p{{0.0, 1.0, 2.0, 3.0, 4.0, 5.0}, {0.0, 0.0, 2.0, 5.0, 0.5, 0.0}};
  const auto w = first_contact(p, 1.0);
  REQUIRE(w);
  CHECK(w->onset == 2.0);
  CHECK(w->duration == 2.0);  // released at t = 4 (0.5 < 1)
  CHECK(w->released);
  // still pressed at the end: the duration runs to the last sample and says so
  const auto held = first_contact({{0.0, 1.0, 2.0}, {0.0, 1.0, 3.0}}, 1.0);
  REQUIRE(held);
  CHECK(held->onset == 1.0);
  CHECK(held->duration == 1.0);
  CHECK_FALSE(held->released);
  CHECK_FALSE(first_contact(p, 6.0));
  CHECK_THROWS_WITH(first_contact(p, 0.0), "contact threshold must be > 0 (got 0)");
}

TEST_CASE("contact: onset and duration errors, simulation sampled at the measurement times",
          "[rig]") {
  const TimeSeries measured{{0.0, 1.0, 2.0, 3.0, 4.0, 5.0}, {0.0, 0.0, 2.0, 5.0, 0.5, 0.0}};
  // on the measured times 0..5 the simulation reads 0, 1.2, 3, 0, 0, 0: onset 1, released 3
  const TimeSeries simulated{{0.0, 1.0, 2.0, 2.5, 5.0}, {0.0, 1.2, 3.0, 0.0, 0.0}};
  const ContactComparison c = compare_contact(measured, simulated, 1.0);
  REQUIRE(c.onset_error);
  CHECK(*c.onset_error == -1.0);
  CHECK(*c.duration_error == 0.0);  // 3 - 1 = 2 against 4 - 2 = 2
  CHECK(c.simulated->duration == 2.0);
  // no simulated contact: no errors, the measured window still reported
  const ContactComparison none = compare_contact(measured, {{0.0, 5.0}, {0.0, 0.0}}, 1.0);
  CHECK(none.measured);
  CHECK_FALSE(none.simulated);
  CHECK_FALSE(none.onset_error);
}
