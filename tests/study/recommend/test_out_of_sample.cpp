// Out of sample (issue 13, "Evidence"): fit on a tiny grid of real simulations, predict at
// points the grid left out, run those points with both models, and check that the rule's
// fitted answer is the one their measured values give, or that the answer said it was
// unreliable. The predicted and measured cost ratios are printed beside each other.
#include <fmt/format.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <vector>

#include "run/runner/point_runner.hpp"
#include "study/grid/grid_expand.hpp"
#include "study/grid/grid_file.hpp"
#include "study/metrics/point_metrics.hpp"
#include "study/recommend/recommendation.hpp"
#include "tests/study/grid/grid_fixtures.hpp"

using namespace ccm;
using study::ImpactModel;

namespace {

// The grid of tests/study/test_study_cli.cpp's tiny study, with three ER and two RLS levels,
// 1 J of impact and 40 ms of contact, so that the errors vary over the grid (at 1 mJ and 10 ms
// they are 1 everywhere): coarse meshes, each run well under a second.
std::string tiny_grid(const std::string& er, const std::string& rls) {
  return fmt::format(R"(title = "out-of-sample"
[axes]
ER = [{}]
RLS = [{}]
KE = [1.0]
[time]
contact_time = 0.02
end = 0.06
output_interval = 1e-3
)",
                     er, rls) +
         std::string(test::kTinyGridBodies);
}

std::vector<study::PointMetrics> run_grid(const std::string& text) {
  const study::GridSpec spec = study::parse_grid(text, "out-of-sample.toml");
  std::vector<study::PointMetrics> out;
  for (const study::GridPoint& p : study::expand_grid(spec))
    out.push_back(study::compute_point_metrics(study::run_point(spec, p, ImpactModel::ccm),
                                               study::run_point(spec, p, ImpactModel::rigid)));
  return out;
}

double worst(const study::ArtifactErrors& e) {
  return std::max({e.u_mean, e.u_max, e.kinetic_energy});
}

}  // namespace

TEST_CASE("out of sample: left-out points get the measured answer or are flagged unreliable",
          "[recommend][out-of-sample][heavy]") {
  const auto grid = run_grid(tiny_grid("1.0, 100.0, 10000.0", "0.5, 1.0"));
  for (const auto& m : grid) REQUIRE(m.usable);
  const study::StudyFits fits = study::fit_study(grid);
  REQUIRE(fits.fits.size() == study::kAllMetrics.size());

  // A threshold that splits the grid (the median of its worst errors), so that the rule has
  // to discriminate instead of answering CCM everywhere.
  std::vector<double> worst_errors;
  for (const auto& m : grid) worst_errors.push_back(worst(m.final_state));
  std::sort(worst_errors.begin(), worst_errors.end());
  const double max_error = 0.5 * (worst_errors[2] + worst_errors[3]);

  // Three points between the grid's levels: ER 10 and 1e3, RLS 0.75 and 0.5.
  const auto left_out = run_grid(tiny_grid("10.0, 1000.0", "0.75"));
  auto more = run_grid(tiny_grid("1000.0", "0.5"));
  std::vector<study::PointMetrics> checked = left_out;
  checked.insert(checked.end(), more.begin(), more.end());
  int agreeing = 0, flagged = 0;
  for (const study::PointMetrics& m : checked) {
    REQUIRE(m.usable);
    const study::RecommendQuery q{
        m.point.modulus_ratio, m.point.length_ratio, m.point.kinetic_energy, {}, max_error};
    const study::Recommendation r = study::recommend(fits, grid, q);
    const study::Decision measured = study::decide_model(study::measured_inputs(m), max_error);
    const std::string line = fmt::format(
        "ER {:g}, RLS {:g}: predicted {} (worst error {:.3g}, RTR {:.3g}{}), measured {} (worst "
        "error {:.3g}, RTR {:.3g}); max error {:.3g}",
        m.point.modulus_ratio, m.point.length_ratio, study::to_string(r.model),
        r.decision.worst_error, r.predicted.runtime_ratio,
        r.reliability.reliable ? "" : ", unreliable", study::to_string(measured.model),
        measured.worst_error, m.runtime_ratio, max_error);
    INFO(line);
    WARN(line);  // the comparison is the evidence: shown in the test log
    CHECK(!r.at_grid_point);
    CHECK((r.model == measured.model || !r.reliability.reliable));
    agreeing += r.model == measured.model;
    flagged += !r.reliability.reliable;
  }
  CHECK(agreeing + flagged >= static_cast<int>(checked.size()));
}
