// Scoring a simulated curve against trials (bench_test/bench_scores.hpp) and finding a channel's
// observable in a history (bench_test/scene_observable.hpp), on synthetic trials whose truth is
// known: a half-sine load pulse recorded at 10 kHz in kN with noise and an offset clock.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>

#include "bench_test/bench_mapping.hpp"
#include "bench_test/bench_scores.hpp"
#include "bench_test/scene_observable.hpp"
#include "config/config_error.hpp"
#include "correlate/cfc_filter.hpp"

using namespace ccm::bench;

namespace {

constexpr double kPulse = 0.004;  // s, the pulse's duration
constexpr double kPeak = 2000.0;  // N

double pulse(double t) {
  return t > 0.0 && t < kPulse ? kPeak * std::sin(std::numbers::pi * t / kPulse) : 0.0;
}

BenchMapping mapping(const std::string& align) {
  return parse_bench_mapping(R"(
[trials]
files = "t*.csv"
time_column = "t"
time_unit = "s"
)" + align + R"(
[[channels]]
name = "load"
column = "load"
unit = "kN"
observable = "plate.force"
filter = "CFC600"
)",
                             "bench.toml");
}

// A trial of the pulse (scaled by `gain`), its clock `offset` s behind the event, noise of 1 % of
// the peak, 10 kHz, in kN.
BenchTrial trial(double offset, double gain, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.01 * kPeak);
  BenchTrial b;
  b.file = "t" + std::to_string(seed) + ".csv";
  for (int k = 0; k < 200; ++k) {
    const double t = -0.005 + k * 1e-4;  // the trial's clock
    b.t.push_back(t);
    b.channels["load"].t.push_back(t);
    b.channels["load"].value.push_back((gain * pulse(t - offset) + noise(rng)) * 1e-3 * 1e3);
  }
  return b;
}

// The simulation: the pulse, output every 20 us, from t = 0 (contact at 1 ms) to 8 ms.
ccm::rig::TimeSeries simulated(double gain) {
  ccm::rig::TimeSeries s;
  for (int k = 0; k <= 400; ++k) {
    s.t.push_back(k * 2e-5);
    s.value.push_back(gain * pulse(k * 2e-5 - 0.001));
  }
  return s;
}

}  // namespace

TEST_CASE("bench scores: a trigger aligns each trial's clock within one sample", "[bench_test]") {
  const BenchMapping m = mapping("[align]\nchannel = \"load\"\nthreshold = 200.0\n");
  // Trial clocks read the event at 0.3, -1.7 and 2.45 ms; the simulation has it at 1 ms.
  const std::vector<BenchTrial> trials = {trial(0.0003, 1.0, 1), trial(-0.0017, 1.0, 2),
                                          trial(0.00245, 1.0, 3)};
  const auto prepared = prepare_trials(m, trials);
  const BenchScores s = score_bench_test(m, prepared, {{"load", simulated(1.0)}});
  REQUIRE(s.clock_shifts.size() == 3);
  CHECK(s.clock_shifts[0] == Approx(0.0007).margin(1e-4));
  CHECK(s.clock_shifts[1] == Approx(0.0027).margin(1e-4));
  CHECK(s.clock_shifts[2] == Approx(-0.00145).margin(1e-4));
  REQUIRE(s.channels.size() == 1);
  for (const ChannelScore& c : s.channels[0].trials) {
    INFO(c.against);
    CHECK(c.rating.grade == ccm::correlate::RatingGrade::excellent);
    // Within one sample (1e-4 s): a difference of two sample times, so up to rounding of them.
    CHECK(std::abs(c.peak_time_error) <= 1e-4 * (1 + 1e-9));
  }
  CHECK(s.channels[0].mean.rating.overall > 0.94);
  // The mean of three trials with 1 % noise lies within the spread, and near the pulse.
  const ChannelCurves& curves = s.channels[0].curves;
  for (std::size_t k = 0; k < curves.t.size(); ++k) {
    CHECK(curves.low[k] <= curves.mean[k]);
    CHECK(curves.mean[k] <= curves.high[k]);
  }
}

TEST_CASE("bench scores: a simulation 20 % off rates lower than the true one", "[bench_test]") {
  const BenchMapping m = mapping("[align]\noffsets = [0.0007, 0.0007]\n");
  const auto prepared = prepare_trials(m, {trial(0.0003, 1.0, 4), trial(0.0003, 1.0, 5)});
  const double right =
      score_bench_test(m, prepared, {{"load", simulated(1.0)}}).channels[0].mean.rating.overall;
  for (double gain : {0.8, 1.2}) {
    INFO("gain " << gain);
    const BenchScores s = score_bench_test(m, prepared, {{"load", simulated(gain)}});
    CHECK(s.channels[0].mean.rating.overall < right - 0.05);
    CHECK(s.channels[0].mean.peak_error == Approx((gain - 1.0) * kPeak).margin(0.03 * kPeak));
  }
}

TEST_CASE("bench scores: a trigger a trial never reaches is refused before any run",
          "[bench_test]") {
  const BenchMapping m = mapping("[align]\nchannel = \"load\"\nthreshold = 5000.0\n");
  CHECK_THROWS_WITH(prepare_trials(m, {trial(0.0, 1.0, 6)}),
                    Catch::Contains("bench.toml:8: align.threshold: t6.csv: channel 'load' never "
                                    "reaches 5000"));
}

TEST_CASE("bench observables: columns, vectors on an axis, rates, and names that name nothing",
          "[bench_test]") {
  const std::vector<std::string> columns = {"time",
                                            "tip.ux",
                                            "tip.uy",
                                            "tip.uz",
                                            "tip.vx",
                                            "tip.vy",
                                            "tip.vz",
                                            "ball.contact_force_x",
                                            "ball.contact_force_y",
                                            "ball.contact_force_z",
                                            "plate.kinetic_energy"};
  ChannelSpec c;
  c.name = "x";
  c.observable_line = 12;
  c.observable = "plate.kinetic_energy";
  CHECK(resolve_observable(c, columns, "b.toml").columns == std::vector<std::size_t>{10});
  c.observable = "ball.contact_force";
  CHECK_THROWS_WITH(resolve_observable(c, columns, "b.toml"),
                    Catch::Contains("b.toml:12: channels.x.observable: 'ball.contact_force' is a "
                                    "vector (three history columns): give its axis"));
  c.axis = std::array<double, 3>{0.0, 0.0, 1.0};
  CHECK(resolve_observable(c, columns, "b.toml").columns == std::vector<std::size_t>{7, 8, 9});
  c.observable = "tip.a";  // the rate of tip.v
  const ResolvedObservable a = resolve_observable(c, columns, "b.toml");
  CHECK(a.columns == std::vector<std::size_t>{4, 5, 6});
  CHECK(a.derivative);
  // v_z = 3 t^2 sampled every 1 ms: the difference quotient is the mean rate over each interval,
  // 3 (t_k + t_{k+1}) ... at the midpoint it is 6 t_mid exactly for a quadratic.
  std::vector<std::vector<double>> rows;
  for (int k = 0; k <= 10; ++k) {
    const double t = 1e-3 * k;
    rows.push_back({t, 0, 0, 0, 0, 0, 3 * t * t, 0, 0, 0, 0});
  }
  const auto rate = simulated_curve(c, a, rows);
  REQUIRE(rate.t.size() == 10);
  for (std::size_t k = 0; k < rate.t.size(); ++k)
    CHECK(rate.value[k] == Approx(6 * rate.t[k]).margin(1e-12));
  c.observable = "plate.kinetic_energie";
  c.axis.reset();
  CHECK_THROWS_WITH(resolve_observable(c, columns, "b.toml"),
                    Catch::Contains("'plate.kinetic_energie' names no output of the scene (did you "
                                    "mean 'plate.kinetic_energy'?)"));
}

TEST_CASE("bench scores: apply_to = simulated leaves a logger's filtered data alone",
          "[bench_test]") {
  // The logger filtered the load at CFC 60 in hardware; the simulation is the raw pulse. Filtered
  // again (apply_to = both) the measured curve is filtered twice and the match suffers; with
  // apply_to = simulated only the simulation is filtered, as the logger filtered the test.
  const auto mapping_with = [](const std::string& apply_to) {
    return parse_bench_mapping(R"(
[trials]
files = "t*.csv"
time_column = "t"
time_unit = "s"
[[channels]]
name = "load"
column = "load"
unit = "N"
observable = "plate.force"
filter = "CFC60"
apply_to = ")" + apply_to + "\"\n",
                               "bench.toml");
  };
  BenchTrial logged;
  logged.file = "t1.csv";
  std::vector<double> raw;
  for (int k = 0; k < 400; ++k) {
    logged.t.push_back(-0.005 + k * 1e-4);
    raw.push_back(pulse(logged.t.back() - 0.001));
  }
  logged.channels["load"] = {logged.t, ccm::correlate::cfc_filter(raw, 60, 1e-4)};
  // The simulation spans 30 ms, long against CFC 60's memory (a few ms): a record that ends
  // while the filtered pulse still rings is filtered differently at its end.
  ccm::rig::TimeSeries sim;
  for (int k = 0; k <= 1500; ++k) {
    sim.t.push_back(k * 2e-5);
    sim.value.push_back(pulse(k * 2e-5 - 0.001));
  }
  const auto rating = [&](const std::string& apply_to) {
    const BenchMapping m = mapping_with(apply_to);
    return score_bench_test(m, prepare_trials(m, {logged}), {{"load", sim}})
        .channels[0]
        .mean.rating.overall;
  };
  CHECK(rating("simulated") > 0.94);
  CHECK(rating("simulated") > rating("both") + 0.02);
  CHECK_THROWS_WITH(
      mapping_with("measured"),
      Catch::Contains("channels[0].apply_to: must be one of \"both\", \"simulated\""));
}
