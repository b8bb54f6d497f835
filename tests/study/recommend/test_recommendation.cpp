// Recommendations from fitted surfaces: KE interpolation, clamping, the one rule, reliability,
// the nearest measured points, other grid axes, refusals.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "study/recommend/recommendation.hpp"

using namespace ccm::study;

namespace {

// Every point of ER {1, 1e2, 1e4, 1e6} x RLS {0.5, 1, 1.5} x KE {10, 100} J: errors
// k (0.3 - 0.05 x) (k = 1 at 10 J, 2 at 100 J; x = log10 ER), RTR = 10^(x / 2), w = error / RTR.
std::vector<PointMetrics> closed_form_points(AxisLevels axes = {}) {
  std::vector<PointMetrics> points;
  int index = 0;
  for (const double ke : {10.0, 100.0})
    for (const double rls : {0.5, 1.0, 1.5})
      for (const double x : {0.0, 2.0, 4.0, 6.0}) {
        PointMetrics m;
        m.point = {index++, std::pow(10.0, x), rls, ke, axes};
        m.usable = true;
        const double e = (ke == 10.0 ? 1.0 : 2.0) * (0.3 - 0.05 * x);
        m.final_state = {e, e, e};
        m.runtime_ratio = std::pow(10.0, x / 2.0);
        m.weighting = {e / m.runtime_ratio, e / m.runtime_ratio, e / m.runtime_ratio};
        m.ccm.normalised_runtime = m.rigid.normalised_runtime = 1.0;
        points.push_back(m);
      }
  return points;
}

RecommendQuery query(double er, double rls, double ke, double max_error = kDefaultMaxError) {
  return {er, rls, ke, {}, max_error};
}

bool mentions(const std::vector<std::string>& lines, const std::string& text) {
  for (const std::string& w : lines)
    if (w.find(text) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_CASE("predictions interpolate linearly in KE between the studied levels", "[recommend]") {
  const auto points = closed_form_points();
  const StudyFits fits = fit_study(points);
  // x = 2: error 0.2 at 10 J, 0.4 at 100 J; halfway in KE: 0.3. RTR 10 at both.
  const Recommendation r = recommend(fits, points, query(1e2, 1.0, 55.0, 0.35));
  CHECK(r.predicted.final_state.u_mean == Approx(0.3).epsilon(1e-9));
  CHECK(r.predicted.final_state.kinetic_energy == Approx(0.3).epsilon(1e-9));
  CHECK(r.predicted.runtime_ratio == Approx(10.0).epsilon(1e-9));
  // w is interpolated in log10 like RTR: the geometric mean of 0.02 and 0.04.
  CHECK(r.predicted.weighting.u_max == Approx(std::sqrt(0.02 * 0.04)).epsilon(1e-9));
  CHECK(r.kinetic_energy_levels_used == std::vector<double>{10.0, 100.0});
  CHECK(r.warnings.empty());
  CHECK(r.clamped.empty());
  // Exact data: every leave-one-out error is rounding.
  CHECK(r.predicted.uncertainty.final_state.u_mean < 1e-12);
  CHECK(r.predicted.uncertainty.log10_runtime_ratio < 1e-12);
  // The rule: 0.3 within 0.35 and RTR 10 > 1.
  CHECK(r.model == ImpactModel::rigid);
  CHECK(r.reliability.reliable);
  CHECK(r.rule == decision_rule_text(0.35));
  const Recommendation strict = recommend(fits, points, query(1e2, 1.0, 55.0, 0.25));
  CHECK(strict.model == ImpactModel::ccm);
  CHECK(strict.reason.find("not all within 0.25") != std::string::npos);
}

TEST_CASE("the cost decides too: accurate but not cheaper is CCM", "[recommend]") {
  const auto points = closed_form_points();
  // ER 1: RTR = 1 exactly, errors 0.3 within 0.5: CCM, since the rigid model saves nothing.
  const Recommendation r = recommend(fit_study(points), points, query(1.0, 1.0, 10.0, 0.5));
  CHECK(r.predicted.runtime_ratio == Approx(1.0).epsilon(1e-9));
  CHECK(r.model == ImpactModel::ccm);
  CHECK(r.decision.rigid_within_error);
  CHECK_FALSE(r.decision.rigid_cheaper);
}

TEST_CASE("predictions outside the measured range are clamped to it, and say so", "[recommend]") {
  const auto points = closed_form_points();
  const Recommendation r = recommend(fit_study(points), points, query(1e-2, 2.0, 500.0));
  CHECK(r.kinetic_energy_levels_used == std::vector<double>{100.0});
  CHECK(mentions(r.warnings, "KE = 500 J lies outside the studied levels [10, 100] J"));
  CHECK(mentions(r.warnings, "log10 ER = -2 lies outside"));
  CHECK(mentions(r.warnings, "RLS = 2 lies outside"));
  // The error surface gives 2 (0.3 + 0.05 x 2) = 0.8; the largest measured at 100 J is 0.6.
  CHECK(r.predicted.final_state.u_mean == Approx(0.6).epsilon(1e-9));
  // log10 RTR = -1 extrapolated; the smallest measured is 10^0.
  CHECK(r.predicted.runtime_ratio == Approx(1.0).epsilon(1e-9));
  CHECK(mentions(r.clamped, "final_u_mean at KE 100 J: the surface gives 0.8"));
  CHECK(mentions(r.clamped, "log10_rtr at KE 100 J: the surface gives -1"));
}

TEST_CASE("above the studied ER the errors are the rigid limit's, those at the highest ER",
          "[recommend]") {
  const auto points = closed_form_points();
  const StudyFits fits = fit_study(points);
  const Recommendation top = recommend(fits, points, query(1e6, 1.0, 10.0));
  const Recommendation above = recommend(fits, points, query(1e8, 1.0, 10.0));
  // Extrapolated, the error surface would give 0.3 - 0.05 x 8 = -0.1 (clamped to 0); at the
  // rigid limit it is the value at x = 6: 0.
  CHECK(above.predicted.final_state.u_mean == Approx(top.predicted.final_state.u_mean));
  CHECK(above.predicted.final_state.u_max == Approx(top.predicted.final_state.u_max));
  CHECK(above.predicted.final_state.kinetic_energy ==
        Approx(top.predicted.final_state.kinetic_energy));
  CHECK_FALSE(mentions(above.clamped, "final_u_mean"));
  CHECK(mentions(above.warnings,
                 "log10 ER = 8 lies above the studied [0, 6] at KE = 10 J: the "
                 "rigid model's errors are those at the highest ER"));
  // The cost ratio keeps growing with ER (10^4 from the surface), within the measured range.
  CHECK(above.predicted.runtime_ratio == Approx(1e3).epsilon(1e-9));
  CHECK(mentions(above.clamped, "log10_rtr at KE 10 J: the surface gives 4"));
  // Below the studied ER nothing is held: the impactor is softer than any studied one.
  const Recommendation below = recommend(fits, points, query(1e-2, 1.0, 10.0));
  CHECK(below.predicted.final_state.u_mean == Approx(0.3).epsilon(1e-9));  // clamped at 0.3
  CHECK(mentions(below.clamped, "final_u_mean at KE 10 J: the surface gives 0.4"));
}

TEST_CASE("the nearest measured points are named with their measured answers", "[recommend]") {
  const auto points = closed_form_points();
  // Grid spacings: 2 decades of ER, 0.5 in RLS, 90 J in KE. From (3, 0.8, 30 J) the points
  // (x 2 or 4, RLS 1, 10 J) are sqrt(0.5^2 + 0.4^2 + (20/90)^2) = 0.678 away, then (2, 0.5).
  const Recommendation r = recommend(fit_study(points), points, query(1e3, 0.8, 30.0));
  REQUIRE(r.nearest.size() == std::size_t(kNearestPoints));
  const double d = std::sqrt(0.25 + 0.16 + std::pow(20.0 / 90.0, 2));
  CHECK(r.nearest[0].distance == Approx(d).epsilon(1e-12));
  CHECK(r.nearest[1].distance == Approx(d).epsilon(1e-12));
  CHECK(r.nearest[0].point.modulus_ratio == Approx(1e2));
  CHECK(r.nearest[1].point.modulus_ratio == Approx(1e4));
  CHECK(r.nearest[2].point.length_ratio == 0.5);
  // At (1e4, 1, 10 J): error 0.1 within 0.1, RTR 100: rigid, measured.
  CHECK(r.nearest[1].decision.model == ImpactModel::rigid);
  CHECK(r.nearest[1].measured.runtime_ratio == Approx(100.0));
  CHECK(r.nearest[0].decision.model == ImpactModel::ccm);
  CHECK_FALSE(r.at_grid_point);
}

TEST_CASE("an answer whose leave-one-out error exceeds its margin is unreliable", "[recommend]") {
  auto points = closed_form_points();
  // Irregular scatter of 0.03 on the errors at 10 J: the fits cannot follow it, their LOO error
  // grows.
  for (PointMetrics& m : points)
    if (m.point.kinetic_energy == 10.0) {
      const double s = 0.03 * std::sin(2.6 * m.point.index * m.point.index + 0.5);
      m.final_state = {m.final_state.u_mean + s, m.final_state.u_max + s,
                       m.final_state.kinetic_energy + s};
    }
  const StudyFits fits = fit_study(points);
  const Recommendation far = recommend(fits, points, query(1e3, 1.0, 10.0, 0.5));
  CHECK(far.reliability.reliable);  // 0.15 +- ~0.03 against 0.5
  const double predicted = far.decision.worst_error;
  const double loo = far.predicted.uncertainty.final_state.u_max;
  REQUIRE(loo > 0.01);
  const Recommendation close =
      recommend(fits, points, query(1e3, 1.0, 10.0, predicted + 0.5 * loo));
  CHECK(close.model == ImpactModel::rigid);
  CHECK_FALSE(close.reliability.reliable);
  CHECK(mentions(close.reliability.reasons, "within its leave-one-out error"));
  CHECK(close.nearest.size() == std::size_t(kNearestPoints));  // named with their measured values
}

TEST_CASE("at a grid point whose measured answer the fits do not reproduce, the answer is flagged",
          "[recommend]") {
  auto points = closed_form_points();
  for (PointMetrics& m : points) m.final_state = {0.05, 0.05, 0.05};  // rigid everywhere but ER 1
  PointMetrics& outlier = points[6];                                  // x = 4, RLS 1, 10 J
  REQUIRE(outlier.point.modulus_ratio == Approx(1e4));
  outlier.final_state.u_max = 0.3;  // measured: CCM
  const StudyFits fits = fit_study(points);
  const Recommendation r = recommend(fits, points, query(1e4, 1.0, 10.0));
  CHECK(r.at_grid_point);
  CHECK(r.nearest.front().point.index == 6);
  CHECK(r.nearest.front().decision.model == ImpactModel::ccm);
  // No low-degree surface follows one point out of twelve: the fit says rigid there.
  CHECK(r.model == ImpactModel::rigid);
  CHECK(r.measured_disagrees);
  CHECK(mentions(r.reliability.reasons, "this is grid point 6, whose measured values give ccm"));
  CHECK_FALSE(r.reliability.reliable);
}

TEST_CASE("other grid axes select their own fits, a swept axis must be named", "[recommend]") {
  std::vector<PointMetrics> points = closed_form_points({{"damping", 0.0}});
  for (PointMetrics m : closed_form_points({{"damping", 1.0}})) {
    m.point.index += 24;
    m.final_state = {0.01, 0.01, 0.01};
    points.push_back(m);
  }
  const StudyFits fits = fit_study(points);
  RecommendQuery q = query(1e2, 1.0, 10.0);
  CHECK_THROWS_WITH(recommend(fits, points, q),
                    "recommend: the study has 2 levels of axis 'damping' (0, 1): choose one with "
                    "--axis damping=VALUE");
  q.axes = {{"damping", 0.5}};
  CHECK_THROWS_WITH(recommend(fits, points, q),
                    Catch::Contains("--axis damping=0.5: not a studied level of damping (levels: "
                                    "0, 1)"));
  q.axes = {{"penalty", 1.0}};
  CHECK_THROWS_WITH(recommend(fits, points, q),
                    Catch::Contains("--axis penalty: the study has no such axis"));
  q.axes = {{"damping", 1.0}};
  const Recommendation r1 = recommend(fits, points, q);
  CHECK(r1.axes == AxisLevels{{"damping", 1.0}});
  CHECK(r1.predicted.final_state.u_max == Approx(0.01).epsilon(1e-9));
  CHECK(r1.model == ImpactModel::rigid);
  for (const NearbyPoint& p : r1.nearest) CHECK(p.point.other_axes.at("damping") == 1.0);
  q.axes = {{"damping", 0.0}};
  CHECK(recommend(fits, points, q).model == ImpactModel::ccm);  // error 0.2
}

TEST_CASE("bad queries and missing fits are refused with a clear message", "[recommend]") {
  const auto points = closed_form_points();
  const StudyFits fits = fit_study(points);
  CHECK_THROWS_WITH(recommend(fits, points, query(0.0, 1.0, 50.0)),
                    "recommend: ER must be positive");
  CHECK_THROWS_WITH(recommend(fits, points, query(1.0, 1.0, 50.0, -0.1)),
                    "recommend: max error must be a non-negative number");
  CHECK_THROWS_WITH(recommend(StudyFits{}, points, query(1.0, 1.0, 50.0)),
                    "recommend: the study has no fits");
  StudyFits partial = fits;
  std::erase_if(partial.fits, [](const MetricFit& f) {
    return f.metric == Metric::log10_w_kinetic_energy && f.kinetic_energy == 100.0;
  });
  CHECK_THROWS_WITH(recommend(partial, points, query(1.0, 1.0, 50.0)),
                    "recommend: no fit of log10_w_kinetic_energy at KE = 100 J");
}

TEST_CASE("every answer states its groups against the studied ranges, and which lie outside",
          "[recommend]") {
  const auto points = closed_form_points();
  const StudyFits fits = fit_study(points);
  const Recommendation in = recommend(fits, points, query(1e3, 1.0, 50.0));
  REQUIRE(in.groups.size() == 3);
  CHECK(in.groups[0].name == "ER");
  CHECK(in.groups[0].low == 1.0);
  CHECK(in.groups[0].high == 1e6);
  CHECK(in.groups[1].low == 0.5);
  CHECK(in.groups[1].high == 1.5);
  CHECK(in.groups[2].low == 10.0);
  CHECK(in.groups[2].high == 100.0);
  for (const GroupRange& g : in.groups) CHECK(g.inside());
  CHECK(in.groups[2].text() == "KE 50 J (inside the studied 10 to 100 J)");

  const Recommendation out = recommend(fits, points, query(1e3, 0.2, 5.0));
  CHECK(out.groups[0].inside());
  CHECK_FALSE(out.groups[1].inside());
  CHECK_FALSE(out.groups[2].inside());
  CHECK(out.groups[1].text() == "RLS 0.2 (OUTSIDE the studied 0.5 to 1.5)");
  CHECK(mentions(out.warnings, "RLS = 0.2 lies outside the studied"));  // and it is warned of
}
