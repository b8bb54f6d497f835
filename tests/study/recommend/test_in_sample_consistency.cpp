// In-sample consistency of the recommendation (issue 13, item 4): at every grid point the rule
// applied to the fitted surfaces gives the same model as applied to the point's measured
// values, or the answer is flagged. On the synthetic study (tests/reports/synthetic_study.hpp)
// the surfaces represent the data exactly, so every answer must agree unflagged; with one
// point's measured errors moved off the surface, the answer there must be flagged.
#include <catch2/catch.hpp>
#include <filesystem>
#include <vector>

#include "db/store/study_store.hpp"
#include "study/recommend/recommendation.hpp"
#include "tests/reports/synthetic_study.hpp"
#include "tests/support/temp_dir.hpp"

using namespace ccm;
using study::ImpactModel;

namespace {

std::vector<study::PointMetrics> synthetic_grid_metrics() {
  const test::TempDir dir;
  const auto file = dir.path / "study.sqlite";
  test::write_synthetic_study(file);
  db::StudyStore store(file);
  store.open_existing_study();
  std::vector<study::PointMetrics> grid;
  for (study::PointMetrics& m : store.load_metrics())
    if (!study::is_convergence_point(m.point)) grid.push_back(std::move(m));
  return grid;
}

// The rule on the measured values, computed here from its definition (not via the library).
ImpactModel measured_answer(const study::PointMetrics& m, double max_error) {
  const auto& e = m.final_state;
  const bool within =
      e.u_mean <= max_error && e.u_max <= max_error && e.kinetic_energy <= max_error;
  return within && m.runtime_ratio > 1.0 ? ImpactModel::rigid : ImpactModel::ccm;
}

// The property: same model, or flagged (measured_disagrees set exactly when they differ).
void check_consistent_or_flagged(const std::vector<study::PointMetrics>& grid, double max_error,
                                 int& agreeing, int& flagged) {
  const study::StudyFits fits = study::fit_study(grid);
  const auto decisions = study::decide_grid_points(fits, grid, max_error);
  REQUIRE(decisions.size() == grid.size() - 1);  // the unstable point is left out
  for (const study::PointDecision& d : decisions) {
    INFO("point " << d.point->point.index << ", max error " << max_error);
    REQUIRE(d.fitted);
    const ImpactModel measured = measured_answer(*d.point, max_error);
    CHECK(d.measured.model == measured);
    CHECK(d.fitted->at_grid_point);
    CHECK(d.fitted->measured_disagrees == (d.fitted->model != measured));
    if (d.fitted->model != measured) CHECK(d.flagged());
    agreeing += d.fitted->model == measured && !d.flagged();
    flagged += d.flagged();
  }
}

}  // namespace

TEST_CASE("in sample: the fitted answer is the measured one at every grid point of an exact study",
          "[recommend][in-sample]") {
  const auto grid = synthetic_grid_metrics();
  REQUIRE(grid.size() == std::size_t(test::kSyntheticPoints));
  // Errors 0.4 (1 - x / 6) at x = 0, 2, 4, 6 are 0.4, 0.267, 0.133, 0: each threshold puts the
  // boundary between grid levels, none on a measured value. (Not above 0.4: at ER 1, RLS 1
  // RTR = 2 sqrt(ER) / 2^RLS is 1 to rounding, and the cost would decide on rounding there.)
  for (const double max_error : {0.05, 0.1, 0.2, 0.3}) {
    int agreeing = 0, flagged = 0;
    check_consistent_or_flagged(grid, max_error, agreeing, flagged);
    CHECK(flagged == 0);
    CHECK(agreeing == test::kSyntheticPoints - 1);
  }
}

TEST_CASE("in sample: a point the surfaces do not reproduce is flagged", "[recommend][in-sample]") {
  auto grid = synthetic_grid_metrics();
  // Point 14: ER 1e4, RLS 0.5, KE 100 J, error 0.133 and RTR 141: rigid at max error 0.2.
  // Its u_max moved to 0.5 (measured: CCM), one point of twelve at its KE: the low-degree
  // surfaces do not follow it.
  study::PointMetrics& moved = grid[14];
  REQUIRE(moved.point.modulus_ratio == Approx(1e4));
  REQUIRE(moved.point.kinetic_energy == 100.0);
  moved.final_state.u_max = 0.5;
  int agreeing = 0, flagged = 0;
  check_consistent_or_flagged(grid, 0.2, agreeing, flagged);
  const study::StudyFits fits = study::fit_study(grid);
  const auto decisions = study::decide_grid_points(fits, grid, 0.2);
  bool moved_flagged = false;
  for (const auto& d : decisions)
    if (d.point->point.index == 14) moved_flagged = d.flagged();
  CHECK(moved_flagged);
  CHECK(flagged >= 1);
}
