// A simulated case against each of its trials: every channel and the contact errors, with
// their spread over the trials, on hand-computed values.
#include <catch2/catch.hpp>
#include <cmath>

#include "rig_models/compare/case_comparison.hpp"
#include "tests/support/tolerance.hpp"

using namespace ccm::rig;
using ccm::test::relative_error;

namespace {

// A trial whose pressure pulse (5 kPa) covers [on, off) on t = 0..5; V_i and theta_a ramps
// scaled by `scale`.
MeasuredTrial trial(double on, double off, double scale) {
  MeasuredTrial m;
  const std::vector<double> t = {0.0, 1.0, 2.0, 3.0, 4.0, 5.0};
  m.impactor_velocity_mps = {t, {0.0, scale, 2 * scale, 3 * scale, 4 * scale, 5 * scale}};
  m.artifact_angle_deg = {t, {0.0, 0.0, scale, scale, 0.0, 0.0}};
  m.pressure_kpa.t = t;
  for (double ti : t) m.pressure_kpa.value.push_back(ti >= on && ti < off ? 5.0 : 0.0);
  return m;
}

}  // namespace

TEST_CASE("case comparison: each channel and the contact, per trial and over the trials", "[rig]") {
  const std::vector<MeasuredTrial> trials = {trial(2.0, 4.0, 1.0), trial(1.0, 4.0, 2.0)};
  const MeasuredTrial sim = trial(2.0, 3.0, 1.0);
  const CaseComparison c = compare_case(
      trials, {sim.impactor_velocity_mps, sim.artifact_angle_deg, sim.pressure_kpa}, 1.0);
  // V_i: identical to trial 1; against trial 2 the differences are -t: RMSE sqrt(55/6)
  CHECK(c.velocity.per_trial[0].rmse == 0.0);
  CHECK(relative_error(c.velocity.per_trial[1].rmse, std::sqrt(55.0 / 6.0)) < 1e-15);
  CHECK(relative_error(c.velocity.rmse.mean, std::sqrt(55.0 / 6.0) / 2.0) < 1e-15);
  // theta_a against trial 2: differences -1 twice in 6 samples
  CHECK(relative_error(c.angle.per_trial[1].rmse, std::sqrt(2.0 / 6.0)) < 1e-15);
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
  // pressure: against trial 1 one sample differs by 5: RMSE 5 / sqrt(6), range 5
  CHECK(relative_error(c.pressure.per_trial[0].rmse, 5.0 / std::sqrt(6.0)) < 1e-15);
  CHECK(relative_error(*c.pressure.per_trial[0].nrmse, 1.0 / std::sqrt(6.0)) < 1e-15);
}

TEST_CASE("case comparison: V_i inside each trial's measured contact window alone", "[rig]") {
  // Trial 1 in contact over [2, 4) (window 2..4, the first sample below the threshold closing
  // it), trial 2 over [1, 4) (window 1..4); the simulation's V_i is trial 1's.
  std::vector<MeasuredTrial> trials = {trial(2.0, 4.0, 1.0), trial(1.0, 4.0, 2.0)};
  trials[0].trial = 1;
  trials[1].trial = 2;
  const MeasuredTrial sim = trial(2.0, 3.0, 1.0);
  const CaseComparison c = compare_case(
      trials, {sim.impactor_velocity_mps, sim.artifact_angle_deg, sim.pressure_kpa}, 1.0);
  CHECK(c.trials == std::vector<int>{1, 2});
  const ChannelInContact& v = c.velocity_in_contact;
  REQUIRE(v.per_trial.size() == 2);
  REQUIRE(v.per_trial[0]);
  REQUIRE(v.per_trial[1]);
  // Trial 1: identical, on its 3 window samples t = 2, 3, 4.
  CHECK(v.per_trial[0]->n_samples == 3);
  CHECK(v.per_trial[0]->rmse == 0.0);
  // Trial 2 on t = 1..4: s - m = -1, -2, -3, -4 -> RMSE sqrt(30/4); range inside 2..8 = 6.
  CHECK(v.per_trial[1]->n_samples == 4);
  CHECK(relative_error(v.per_trial[1]->rmse, std::sqrt(7.5)) < 1e-15);
  CHECK(relative_error(*v.per_trial[1]->nrmse, std::sqrt(7.5) / 6.0) < 1e-15);
  CHECK(v.per_trial[1]->peak_measured == 8.0);  // the window's, not the trial's (10)
  REQUIRE(v.rmse);
  CHECK(relative_error(v.rmse->mean, std::sqrt(7.5) / 2.0) < 1e-15);
  // Over the whole window the same trial differs at every sample: a different figure.
  CHECK(relative_error(c.velocity.per_trial[1].rmse, std::sqrt(55.0 / 6.0)) < 1e-15);

  // A trial without contact, and one whose contact holds a single V_i sample, have none.
  std::vector<MeasuredTrial> odd = {trial(9.0, 9.0, 1.0), trial(4.0, 5.0, 1.0)};
  odd[1].impactor_velocity_mps = {{0.0, 1.0, 4.5}, {0.0, 1.0, 4.5}};
  const CaseComparison n =
      compare_case(odd, {sim.impactor_velocity_mps, sim.artifact_angle_deg, sim.pressure_kpa}, 1.0);
  REQUIRE(n.velocity_in_contact.per_trial.size() == 2);
  CHECK_FALSE(n.velocity_in_contact.per_trial[0]);
  CHECK_FALSE(n.velocity_in_contact.per_trial[1]);
  CHECK_FALSE(n.velocity_in_contact.rmse);
}

TEST_CASE("case comparison: the trial that drives the run is left out of the scores", "[rig]") {
  std::vector<MeasuredTrial> trials = {trial(2.0, 4.0, 1.0), trial(1.0, 4.0, 2.0),
                                       trial(2.0, 3.0, 1.5)};
  for (int k = 0; k < 3; ++k) trials[static_cast<size_t>(k)].trial = k + 1;
  const std::vector<MeasuredTrial> without_2 = scored_trials(trials, 2);
  REQUIRE(without_2.size() == 2);
  CHECK(without_2[0].trial == 1);
  CHECK(without_2[1].trial == 3);
  CHECK(scored_trials(trials, std::nullopt).size() == 3);
  // Scored on trials 1 and 3, the per-trial lists are theirs, in that order.
  const MeasuredTrial& sim = trials[1];
  const CaseComparison c = compare_case(
      without_2, {sim.impactor_velocity_mps, sim.artifact_angle_deg, sim.pressure_kpa}, 1.0);
  CHECK(c.trials == std::vector<int>{1, 3});
  REQUIRE(c.velocity.per_trial.size() == 2);
  CHECK(c.velocity.per_trial[0].rmse > 0.0);  // trial 2 itself (RMSE 0) is not among them
  CHECK(c.velocity.per_trial[1].rmse > 0.0);
  CHECK(c.contact.size() == 2);
}
