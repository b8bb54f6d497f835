// A simulated case against each of its trials, through the bench test's path
// (bench_test/rig_case_scores.hpp): every channel and the contact errors, with their spread over
// the trials, on hand-computed values. The trials sample every second on t = 0..12; the run's
// curves every 10 ms, their pressure edges half-way between the trials' instants, so that the
// sensor model's low-pass (20 Hz here) has settled at every instant (to 1e-40: the bilinear
// filter's pole is 0.16 per 10 ms step) and the hand values hold to round-off.
#include <catch2/catch.hpp>
#include <cmath>

#include "bench_test/rig_case_scores.hpp"
#include "rig_models/compare/case_comparison.hpp"
#include "tests/support/tolerance.hpp"

using namespace ccm::rig;
using ccm::bench::RigRunCurves;
using ccm::test::relative_error;

namespace {

constexpr PressureSensor kSensor{1.0, 20.0};

// A trial whose pressure pulse (5 kPa) covers [on, off); V_i = scale t; theta_a = scale at t =
// 2, 3.
MeasuredTrial trial(double on, double off, double scale, int number = 0) {
  MeasuredTrial m;
  m.trial = number;
  for (int k = 0; k <= 12; ++k) {
    const double t = k;
    m.impactor_velocity_mps.t.push_back(t);
    m.impactor_velocity_mps.value.push_back(scale * t);
    m.artifact_angle_deg.t.push_back(t);
    m.artifact_angle_deg.value.push_back(k == 2 || k == 3 ? scale : 0.0);
    m.pressure_kpa.t.push_back(t);
    m.pressure_kpa.value.push_back(t >= on && t < off ? 5.0 : 0.0);
  }
  return m;
}

// The run's curves every 10 ms: V_i = v t, theta_a = a over (1.5, 3.5), P_raw 5 kPa over
// (on - 0.5, off - 0.5): at the trials' instants, a contact over [on, off).
RigRunCurves run(double on, double off, double v, double a) {
  RigRunCurves r;
  for (int k = 0; k <= 1200; ++k) {
    const double t = 0.01 * k;
    for (TimeSeries* s : {&r.velocity_mps, &r.angle_deg, &r.pressure_raw_kpa}) s->t.push_back(t);
    r.velocity_mps.value.push_back(v * t);
    r.angle_deg.value.push_back(t > 1.5 && t < 3.5 ? a : 0.0);
    r.pressure_raw_kpa.value.push_back(t > on - 0.5 && t < off - 0.5 ? 5.0 : 0.0);
  }
  return r;
}

CaseComparison scored(const std::vector<MeasuredTrial>& trials, const RigRunCurves& r) {
  return ccm::bench::score_rig_case("RX025", trials, r, kSensor);
}

}  // namespace

TEST_CASE("case comparison: each channel and the contact, per trial and over the trials", "[rig]") {
  const std::vector<MeasuredTrial> trials = {trial(2.0, 4.0, 1.0), trial(1.0, 4.0, 2.0)};
  const CaseComparison c = scored(trials, run(2.0, 3.0, 1.0, 1.0));
  // V_i: identical to trial 1; against trial 2 the differences are -t: RMSE sqrt(650/13)
  CHECK(c.velocity.per_trial[0].rmse < 1e-15);
  CHECK(relative_error(c.velocity.per_trial[1].rmse, std::sqrt(50.0)) < 1e-12);
  CHECK(relative_error(c.velocity.rmse.mean, std::sqrt(50.0) / 2.0) < 1e-12);
  // theta_a against trial 2: differences -1 twice in 13 samples
  CHECK(relative_error(c.angle.per_trial[1].rmse, std::sqrt(2.0 / 13.0)) < 1e-12);
  // contact: simulated [2, 3); trial 1 [2, 4): onset 0, duration -1; trial 2 [1, 4): +1, -2
  REQUIRE(c.contact.size() == 2);
  CHECK(*c.contact[0].onset_error == 0.0);
  CHECK(*c.contact[0].duration_error == -1.0);
  CHECK(*c.contact[1].onset_error == 1.0);
  CHECK(*c.contact[1].duration_error == -2.0);
  REQUIRE(c.onset_error);
  CHECK(c.onset_error->mean == 0.5);
  CHECK(relative_error(c.onset_error->std_dev, std::sqrt(0.5)) < 1e-15);
  CHECK(c.duration_error->mean == -1.5);
  // pressure: against trial 1 one sample differs by 5: RMSE 5 / sqrt(13), range 5
  CHECK(relative_error(c.pressure.per_trial[0].rmse, 5.0 / std::sqrt(13.0)) < 1e-12);
  CHECK(relative_error(*c.pressure.per_trial[0].nrmse, 1.0 / std::sqrt(13.0)) < 1e-12);
}

TEST_CASE("case comparison: V_i inside each trial's measured contact window alone", "[rig]") {
  // Trial 1 in contact over [2, 4) (window 2..4, the first sample below the threshold closing
  // it), trial 2 over [1, 4) (window 1..4); the simulation's V_i is trial 1's.
  const std::vector<MeasuredTrial> trials = {trial(2.0, 4.0, 1.0, 1), trial(1.0, 4.0, 2.0, 2)};
  const CaseComparison c = scored(trials, run(2.0, 3.0, 1.0, 1.0));
  CHECK(c.trials == std::vector<int>{1, 2});
  const ChannelInContact& v = c.velocity_in_contact;
  REQUIRE(v.per_trial.size() == 2);
  REQUIRE(v.per_trial[0]);
  REQUIRE(v.per_trial[1]);
  // Trial 1: identical, on its 3 window samples t = 2, 3, 4.
  CHECK(v.per_trial[0]->n_samples == 3);
  CHECK(v.per_trial[0]->rmse < 1e-15);
  // Trial 2 on t = 1..4: s - m = -1, -2, -3, -4 -> RMSE sqrt(30/4); range inside 2..8 = 6.
  CHECK(v.per_trial[1]->n_samples == 4);
  CHECK(relative_error(v.per_trial[1]->rmse, std::sqrt(7.5)) < 1e-12);
  CHECK(relative_error(*v.per_trial[1]->nrmse, std::sqrt(7.5) / 6.0) < 1e-12);
  CHECK(v.per_trial[1]->peak_measured == 8.0);  // the window's, not the trial's (24)
  REQUIRE(v.rmse);
  CHECK(relative_error(v.rmse->mean, std::sqrt(7.5) / 2.0) < 1e-12);
  // Over the whole window the same trial differs at every sample: a different figure.
  CHECK(relative_error(c.velocity.per_trial[1].rmse, std::sqrt(50.0)) < 1e-12);

  // A trial without contact, and one whose contact [4, 5] holds a single V_i sample (V_i every
  // 1.2 s: 4.8), have none.
  std::vector<MeasuredTrial> odd = {trial(99.0, 99.0, 1.0), trial(4.0, 5.0, 1.0)};
  odd[1].impactor_velocity_mps = {};
  for (int k = 0; k <= 10; ++k) {
    odd[1].impactor_velocity_mps.t.push_back(1.2 * k);
    odd[1].impactor_velocity_mps.value.push_back(1.2 * k);
  }
  const CaseComparison n = scored(odd, run(2.0, 3.0, 1.0, 1.0));
  REQUIRE(n.velocity_in_contact.per_trial.size() == 2);
  CHECK_FALSE(n.velocity_in_contact.per_trial[0]);
  CHECK_FALSE(n.velocity_in_contact.per_trial[1]);
  CHECK_FALSE(n.velocity_in_contact.rmse);
}

TEST_CASE("case comparison: the trial that drives the run is left out of the scores", "[rig]") {
  std::vector<MeasuredTrial> trials = {trial(2.0, 4.0, 1.0, 1), trial(1.0, 4.0, 2.0, 2),
                                       trial(2.0, 3.0, 1.5, 3)};
  const std::vector<MeasuredTrial> without_2 = scored_trials(trials, 2);
  REQUIRE(without_2.size() == 2);
  CHECK(without_2[0].trial == 1);
  CHECK(without_2[1].trial == 3);
  CHECK(scored_trials(trials, std::nullopt).size() == 3);
  // Scored on trials 1 and 3 (the run is trial 2's), the per-trial lists are theirs, in order.
  const CaseComparison c = scored(without_2, run(1.0, 4.0, 2.0, 2.0));
  CHECK(c.trials == std::vector<int>{1, 3});
  REQUIRE(c.velocity.per_trial.size() == 2);
  CHECK(c.velocity.per_trial[0].rmse > 0.0);  // trial 2 itself (RMSE 0) is not among them
  CHECK(c.velocity.per_trial[1].rmse > 0.0);
  CHECK(c.contact.size() == 2);
}
