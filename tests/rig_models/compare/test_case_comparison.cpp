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
