// Recommendations from fitted surfaces: KE interpolation, the two decision rules, warnings.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "study/recommend/recommendation.hpp"

using namespace ccm::study;

namespace {

// A fit whose surface is the plane z = a + b x over log10 ER in [0, 6], RLS in [0.5, 1.5].
MetricFit plane(Metric metric, double ke, double a, double b) {
  MetricFit f;
  f.metric = metric;
  f.kinetic_energy = ke;
  f.fit.surface.degree = {1, 0};
  f.fit.surface.terms = {{0, 0, a}, {1, 0, b}};
  f.fit.x_min = 0.0;
  f.fit.x_max = 6.0;
  f.fit.y_min = 0.5;
  f.fit.y_max = 1.5;
  return f;
}

// At 10 J: errors 0.3 - 0.05 x, RTR 1 + x, w 0.02; at 100 J everything doubled but RTR.
StudyFits two_levels() {
  StudyFits fits;
  for (const double ke : {10.0, 100.0}) {
    const double k = ke == 10.0 ? 1.0 : 2.0;
    for (const Metric m : {Metric::final_u_mean, Metric::final_u_max, Metric::final_kinetic_energy})
      fits.fits.push_back(plane(m, ke, k * 0.3, k * -0.05));
    fits.fits.push_back(plane(Metric::runtime_ratio, ke, 1.0, 1.0));
    for (const Metric m : {Metric::w_u_mean, Metric::w_u_max, Metric::w_kinetic_energy})
      fits.fits.push_back(plane(m, ke, k * 0.02, 0.0));
  }
  return fits;
}

bool mentions(const std::vector<std::string>& warnings, const std::string& text) {
  for (const std::string& w : warnings)
    if (w.find(text) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_CASE("predictions interpolate linearly in KE between the studied levels", "[recommend]") {
  RecommendQuery q;
  q.modulus_ratio = 1e2;  // x = 2: error 0.2 at 10 J, 0.4 at 100 J
  q.length_ratio = 1.0;
  q.kinetic_energy = 55.0;  // halfway: 0.3
  const Recommendation r = recommend(two_levels(), q);
  CHECK(r.predicted.final_state.u_mean == Approx(0.3).epsilon(1e-12));
  CHECK(r.predicted.final_state.kinetic_energy == Approx(0.3).epsilon(1e-12));
  CHECK(r.predicted.runtime_ratio == Approx(3.0).epsilon(1e-12));
  CHECK(r.predicted.weighting.u_max == Approx(0.03).epsilon(1e-12));
  CHECK(r.kinetic_energy_levels_used == std::vector<double>{10.0, 100.0});
  CHECK(r.warnings.empty());
  // w = 0.03 < 0.1: rigid is enough by the weighting rule.
  CHECK(r.model == ImpactModel::rigid);
  CHECK(r.reason.find("below the threshold") != std::string::npos);
}

TEST_CASE("the max-error threshold decides by the predicted final-state errors", "[recommend]") {
  RecommendQuery q;
  q.modulus_ratio = 1e2;
  q.kinetic_energy = 55.0;  // errors all 0.3
  q.max_error = 0.35;
  CHECK(recommend(two_levels(), q).model == ImpactModel::rigid);
  q.max_error = 0.25;
  const Recommendation r = recommend(two_levels(), q);
  CHECK(r.model == ImpactModel::ccm);
  CHECK(r.reason.find("not all below the maximum error 0.25") != std::string::npos);
}

TEST_CASE("the weighting rule recommends CCM when w reaches the threshold", "[recommend]") {
  RecommendQuery q;
  q.modulus_ratio = 1.0;
  q.kinetic_energy = 100.0;  // exactly a level: w = 0.04
  q.w_threshold = 0.04;
  const Recommendation r = recommend(two_levels(), q);
  CHECK(r.kinetic_energy_levels_used == std::vector<double>{100.0});
  CHECK(r.model == ImpactModel::ccm);
  q.w_threshold = 0.0401;
  CHECK(recommend(two_levels(), q).model == ImpactModel::rigid);
}

TEST_CASE("queries outside the studied grid are answered with warnings", "[recommend]") {
  RecommendQuery q;
  q.modulus_ratio = 1e8;   // log10 ER = 8 > 6
  q.length_ratio = 2.0;    // > 1.5
  q.kinetic_energy = 500;  // > 100 J: the 100 J surfaces are used
  const Recommendation r = recommend(two_levels(), q);
  CHECK(r.kinetic_energy_levels_used == std::vector<double>{100.0});
  CHECK(mentions(r.warnings, "KE = 500 J lies outside the studied levels [10, 100] J"));
  CHECK(mentions(r.warnings, "log10 ER = 8 lies outside"));
  CHECK(mentions(r.warnings, "RLS = 2 lies outside"));
  // 2 (0.3 - 0.05 x 8) = -0.2: extrapolation left the physical range, and says so.
  CHECK(r.predicted.final_state.u_mean == Approx(-0.2).epsilon(1e-12));
  CHECK(mentions(r.warnings, "a predicted final-state error is negative"));
  CHECK(r.warnings.size() == 4);
}

TEST_CASE("bad queries and missing fits are refused with a clear message", "[recommend]") {
  RecommendQuery q;
  q.kinetic_energy = 50.0;
  q.modulus_ratio = 0.0;
  CHECK_THROWS_WITH(recommend(two_levels(), q), "recommend: ER must be positive");
  q.modulus_ratio = 1.0;
  CHECK_THROWS_WITH(recommend(StudyFits{}, q), "recommend: the study has no fits");
  StudyFits partial = two_levels();
  partial.fits.pop_back();  // w_kinetic_energy at 100 J
  CHECK_THROWS_WITH(recommend(partial, q), "recommend: no fit of w_kinetic_energy at KE = 100 J");
}
