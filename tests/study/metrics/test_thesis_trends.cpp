// The thesis-trend figures of one point (study/metrics/thesis_trends.hpp) from the two synthetic
// runs of synthetic_runs.hpp, against values worked out by hand.
#include <catch2/catch.hpp>

#include "study/metrics/thesis_trends.hpp"
#include "tests/study/metrics/synthetic_runs.hpp"
#include "tests/support/tolerance.hpp"

using namespace ccm::study;
using ccm::test::relative_error;
using ccm::test::synthetic_run;

TEST_CASE("thesis trends of two synthetic runs match the hand computation", "[metrics]") {
  const RunRecord c = synthetic_run(ImpactModel::ccm);
  const RunRecord r = synthetic_run(ImpactModel::rigid);
  const TrendRow t = thesis_trend(c, r);
  // KE: ccm 0, 4, 2, 1 against rigid 0, 4, 4, 4: largest gap 3 over the rigid peak 4.
  CHECK(relative_error(t.ke_gap, 0.75) < 1e-15);
  CHECK(relative_error(t.ke_ratio, 0.25) < 1e-15);     // 1 / 4 at t_f
  CHECK(relative_error(t.u_mean_ratio, 0.5) < 1e-15);  // 2 / 4
  CHECK(relative_error(t.u_max_ratio, 0.5) < 1e-15);   // 3 / 6
  CHECK(t.point.index == c.point.index);
  RunRecord still = r;
  for (double& v : still.artifact.kinetic_energy) v = 0.0;
  CHECK_THROWS_WITH(thesis_trend(c, still), Catch::Contains("does not move"));
  RunRecord shorter = r;
  shorter.artifact.kinetic_energy.pop_back();
  CHECK_THROWS_WITH(thesis_trend(c, shorter), Catch::Contains("differ in length"));
}
