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
    CHECK(c.rating->grade == ccm::correlate::RatingGrade::excellent);
    // Within one sample (1e-4 s): a difference of two sample times, so up to rounding of them.
    CHECK(std::abs(c.peak_time_error) <= 1e-4 * (1 + 1e-9));
  }
  CHECK(s.channels[0].mean->rating->overall > 0.94);
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
      score_bench_test(m, prepared, {{"load", simulated(1.0)}}).channels[0].mean->rating->overall;
  for (double gain : {0.8, 1.2}) {
    INFO("gain " << gain);
    const BenchScores s = score_bench_test(m, prepared, {{"load", simulated(gain)}});
    CHECK(s.channels[0].mean->rating->overall < right - 0.05);
    CHECK(s.channels[0].mean->peak_error == Approx((gain - 1.0) * kPeak).margin(0.03 * kPeak));
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
        .mean->rating->overall;
  };
  CHECK(rating("simulated") > 0.94);
  CHECK(rating("simulated") > rating("both") + 0.02);
  CHECK_THROWS_WITH(
      mapping_with("measured"),
      Catch::Contains("channels[0].apply_to: must be one of \"both\", \"simulated\""));
}

namespace {

// A contact of the pressure channel "p" (5 kPa from `on` to `off` s, 1 kHz over [0, 0.1] s) and
// a velocity "v" = t.
BenchTrial contact_trial(const std::string& name, std::optional<std::pair<double, double>> on_off) {
  BenchTrial b;
  b.file = name;
  for (int k = 0; k <= 100; ++k) {
    const double t = k * 1e-3;
    b.t.push_back(t);
    const bool in = on_off && t >= on_off->first - 1e-12 && t < on_off->second - 1e-12;
    b.channels["p"].t.push_back(t);
    b.channels["p"].value.push_back(in ? 5e3 : 0.0);
    for (const char* v : {"v", "v_contact"}) {
      b.channels[v].t.push_back(t);
      b.channels[v].value.push_back(t);
    }
  }
  return b;
}

BenchMapping contact_mapping(const std::string& p_extra) {
  return parse_bench_mapping(R"(
[trials]
files = "t*.csv"
time_column = "t"
time_unit = "s"

[[events]]
name = "contact"
channel = "p"
threshold = 1000.0

[[channels]]
name = "p"
column = "p"
unit = "Pa"
observable = "sensor.pressure"
)" + p_extra + R"(

[[channels]]
name = "v"
column = "v"
unit = "m/s"
observable = "tip.v"

[[channels]]
name = "v_contact"
column = "v"
unit = "m/s"
observable = "tip.v"
window = "contact"
)",
                             "bench.toml");
}

// The simulation: the contact from 12 to 35 ms, v = t + 0.5, output every 0.1 ms.
std::map<std::string, ccm::rig::TimeSeries> contact_simulation() {
  std::map<std::string, ccm::rig::TimeSeries> s;
  for (int k = 0; k <= 1000; ++k) {
    const double t = k * 1e-4;
    for (const char* c : {"p", "v", "v_contact"}) s[c].t.push_back(t);
    s["p"].value.push_back(t >= 0.012 - 1e-12 && t < 0.035 - 1e-12 ? 5e3 : 0.0);
    s["v"].value.push_back(t + 0.5);
    s["v_contact"].value.push_back(t + 0.5);
  }
  return s;
}

}  // namespace

TEST_CASE("bench scores: an event's onset and duration errors, and a channel scored inside it",
          "[bench_test]") {
  const BenchMapping m = contact_mapping("");
  // Trial 1: contact from 10 to 30 ms; trial 2: from 10 to 14 ms (5 samples of v in it); trial 3:
  // no contact.
  const auto prepared = prepare_trials(
      m, {contact_trial("t1.csv", std::pair{0.010, 0.030}),
          contact_trial("t2.csv", std::pair{0.010, 0.014}), contact_trial("t3.csv", {})});
  const BenchScores s = score_bench_test(m, prepared, contact_simulation());
  REQUIRE(s.events.size() == 1);
  const auto& e = s.events[0].per_trial;
  REQUIRE(e.size() == 3);
  // On the measured instants (1 ms): the simulated onset at 12 ms, the release at 35 ms.
  CHECK(e[0].measured->onset == Approx(0.010).margin(1e-12));
  CHECK(e[0].measured->duration == Approx(0.020).margin(1e-12));
  CHECK(*e[0].onset_error == Approx(0.002).margin(1e-12));
  CHECK(*e[0].duration_error == Approx(0.003).margin(1e-12));
  CHECK(*e[1].duration_error == Approx(0.023 - 0.004).margin(1e-12));
  CHECK_FALSE(e[2].measured);
  CHECK_FALSE(e[2].onset_error);
  // Trial 3's pressure is zero everywhere: scored, without a rating (it has no corridor).
  CHECK(s.channels[0].trials[2].samples == 101);
  CHECK_FALSE(s.channels[0].trials[2].rating);

  const ChannelResult& in_contact = s.channels[2];
  REQUIRE(in_contact.trials.size() == 2);  // trial 3 has no contact
  CHECK(in_contact.trials[0].against == "t1.csv");
  CHECK(in_contact.trials[0].samples == 21);  // 10 to 30 ms, both ends
  CHECK(in_contact.trials[0].rmse == Approx(0.5).epsilon(1e-12));
  CHECK(*in_contact.trials[0].nrmse == Approx(0.5 / 0.020).epsilon(1e-9));
  CHECK(in_contact.trials[0].rating);
  CHECK(in_contact.trials[1].samples == 5);  // 10 to 14 ms
  CHECK_FALSE(in_contact.trials[1].rating);  // fewer than a rating needs
  REQUIRE(in_contact.mean);                  // over the union of the windows, 10 to 30 ms
  CHECK(in_contact.mean->samples == 21);
  // The whole-span channel: every sample of the 101.
  CHECK(s.channels[1].trials[0].samples == 101);
  CHECK(s.channels[1].trials[0].rmse == Approx(0.5).epsilon(1e-12));
}

TEST_CASE("bench scores: the deadband before or after the filter, as the mapping says",
          "[bench_test]") {
  // A step of 5 kPa at 12 ms low-passed at 20 Hz: after the filter, a 2 kPa deadband zeroes the
  // rise below 2 kPa; before it, it leaves the step (above 2 kPa) and the rise is kept.
  const std::string filter = "filter = \"low_pass\"\ncutoff = 20\ndeadband = 2000\n";
  const auto trials = std::vector<BenchTrial>{contact_trial("t1.csv", std::pair{0.010, 0.030})};
  const BenchMapping after = contact_mapping(filter + "apply_to = \"simulated\"\n");
  const BenchMapping before =
      contact_mapping(filter + "apply_to = \"simulated\"\ndeadband_first = true\n");
  const auto sim = contact_simulation();
  const ChannelCurves a =
      score_bench_test(after, prepare_trials(after, trials), sim).channels[0].curves;
  const ChannelCurves b =
      score_bench_test(before, prepare_trials(before, trials), sim).channels[0].curves;
  // At 14 ms the filtered step has risen to 5 kPa (1 - exp(-2 pi 20 t)) = 1.1 kPa, t = 2 ms
  // after the step and half an output interval (the bilinear filter averages each sample with
  // the one before: it leads the analog response by half a step); the rest of the gap is the
  // bilinear map's frequency warping, O((2 pi 20 dt)^2) = 1.6e-4.
  const std::size_t k = 14;
  REQUIRE(a.t[k] == Approx(0.014).margin(1e-12));
  CHECK(a.simulated[k] == 0.0);
  CHECK(b.simulated[k] ==
        Approx(5e3 * (1.0 - std::exp(-2.0 * std::numbers::pi * 20.0 * 0.00205))).epsilon(1e-3));
  CHECK(b.simulated[k] < 2e3);  // below the deadband, kept
}
