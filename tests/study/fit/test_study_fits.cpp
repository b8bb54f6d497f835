// Fits over a whole study: one surface per KE level and metric, unusable points left out.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "study/fit/study_fits.hpp"

using namespace ccm::study;

namespace {

// A usable point whose every metric is a known polynomial of (log10 ER, RLS), scaled by KE.
PointMetrics synthetic_point(int index, double er, double rls, double ke) {
  PointMetrics m;
  m.point = {index, er, rls, ke, {}};
  m.usable = true;
  const double x = std::log10(er), s = ke / 100.0;
  m.final_state = {s * (0.6 - 0.1 * x), s * (0.3 - 0.05 * x + 0.1 * rls), s * 0.5};
  m.runtime_ratio = 1.0 + 2.0 * x;
  m.weighting = {s * (0.06 - 0.01 * x), s * 0.02 * rls, s * 0.05};
  m.cumulative = {s, 2.0 * s, 3.0 * s};
  m.ccm.normalised_runtime = 2.0 * std::sqrt(er);   // log10 NT = log10 2 + x / 2
  m.rigid.normalised_runtime = std::pow(2.0, rls);  // log10 NT = y log10 2
  return m;
}

}  // namespace

TEST_CASE("every metric is fitted per KE level; unusable points are excluded visibly", "[fit]") {
  std::vector<PointMetrics> points;
  int index = 0;
  for (const double ke : {10.0, 100.0})
    for (const double er : {1.0, 1e2, 1e4, 1e6})
      for (const double rls : {0.5, 1.0, 1.5})
        points.push_back(synthetic_point(index++, er, rls, ke));
  points[4].usable = false;
  points[4].excluded_reason = "ccm run unstable: energy balance";

  const StudyFits fits = fit_study(points);
  CHECK(fits.kinetic_energy_levels() == std::vector<double>{10.0, 100.0});
  CHECK(fits.fits.size() == 2 * kAllMetrics.size());
  CHECK(fits.notes.empty());
  REQUIRE(fits.excluded.size() == 1);
  CHECK(fits.excluded[0].point_index == 4);
  CHECK(fits.excluded[0].reason == "ccm run unstable: energy balance");

  const MetricFit* rtr = fits.find(Metric::runtime_ratio, 10.0);
  REQUIRE(rtr);
  CHECK(rtr->fit.samples.size() == 11);  // 12 points at 10 J minus the unusable one
  for (const SurfaceSample& s : rtr->fit.samples) CHECK(s.id != 4);
  CHECK(rtr->fit.surface.degree == SurfaceDegree{1, 0});
  CHECK(rtr->fit.surface(3.0, 1.0) == Approx(7.0).margin(1e-10));
  const MetricFit* u_max = fits.find(Metric::final_u_max, 100.0);
  REQUIRE(u_max);
  CHECK(u_max->fit.samples.size() == 12);
  CHECK(u_max->fit.surface(2.0, 1.2) == Approx(0.3 - 0.1 + 0.12).margin(1e-10));
  CHECK(fits.find(Metric::runtime_ratio, 50.0) == nullptr);

  // NT is fitted in log10 (Fig. 2-28): power laws in ER and RLS come out as planes.
  const MetricFit* nt_ccm = fits.find(Metric::log10_nt_ccm, 100.0);
  const MetricFit* nt_rigid = fits.find(Metric::log10_nt_rigid, 100.0);
  REQUIRE(nt_ccm);
  REQUIRE(nt_rigid);
  CHECK(nt_ccm->fit.surface.degree == SurfaceDegree{1, 0});
  CHECK(nt_rigid->fit.surface.degree == SurfaceDegree{0, 1});
  CHECK(nt_ccm->fit.surface(2.5, 0.7) == Approx(std::log10(2.0) + 1.25).margin(1e-10));
  CHECK(nt_rigid->fit.surface(2.5, 0.7) == Approx(0.7 * std::log10(2.0)).margin(1e-10));
}
