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
  m.runtime_ratio = 2.0 * std::sqrt(er) / std::pow(2.0, rls);  // log10: a plane
  m.weighting = {s * 0.06 / m.runtime_ratio, s * 0.02 * rls / m.runtime_ratio, 0.0};
  m.cumulative = {s, 2.0 * s, 3.0 * s};
  m.ccm.normalised_runtime = 2.0 * std::sqrt(er);   // log10 NT = log10 2 + x / 2
  m.rigid.normalised_runtime = std::pow(2.0, rls);  // log10 NT = y log10 2
  return m;
}

}  // namespace

TEST_CASE("every metric is fitted per KE level, unusable points are excluded visibly", "[fit]") {
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

  // RTR and w are fitted in log10: RTR = 2 sqrt(ER) / 2^RLS is the plane
  // log10 2 + x / 2 - y log10 2, recovered exactly (degree (1, 1) would fit it too: the
  // leave-one-out tie goes to the fewer terms).
  const MetricFit* rtr = fits.find(Metric::log10_runtime_ratio, 10.0);
  REQUIRE(rtr);
  CHECK(rtr->fit.samples.size() == 11);  // 12 points at 10 J minus the unusable one
  for (const SurfaceSample& s : rtr->fit.samples) CHECK(s.id != 4);
  CHECK(rtr->fit.surface.degree == SurfaceDegree{1, 1});
  CHECK(rtr->fit.surface(3.0, 1.0) ==
        Approx(std::log10(2.0) + 1.5 - std::log10(2.0)).margin(1e-10));
  // w_u_mean = 0.06 s / RTR: log10 w is a plane too; w_KE = 0 is floored at kWeightFloor.
  const MetricFit* w = fits.find(Metric::log10_w_u_mean, 100.0);
  REQUIRE(w);
  CHECK(w->fit.surface(2.0, 1.0) ==
        Approx(std::log10(0.06) - std::log10(2.0) - 1.0 + std::log10(2.0)).margin(1e-10));
  const MetricFit* w_ke = fits.find(Metric::log10_w_kinetic_energy, 100.0);
  REQUIRE(w_ke);
  CHECK(w_ke->fit.surface.degree == SurfaceDegree{0, 0});
  CHECK(w_ke->fit.surface(2.0, 1.0) == Approx(std::log10(kWeightFloor)).margin(1e-10));
  const MetricFit* u_max = fits.find(Metric::final_u_max, 100.0);
  REQUIRE(u_max);
  CHECK(u_max->fit.samples.size() == 12);
  CHECK(u_max->fit.surface(2.0, 1.2) == Approx(0.3 - 0.1 + 0.12).margin(1e-10));
  CHECK(fits.find(Metric::log10_runtime_ratio, 50.0) == nullptr);

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

TEST_CASE("fits are grouped by KE and the other axes' levels, convergence points are left out",
          "[fit]") {
  std::vector<PointMetrics> points;
  int index = 0;
  for (const double damping : {0.0, 1.0})
    for (const double er : {1.0, 1e2, 1e4, 1e6})
      for (const double rls : {0.5, 1.0, 1.5}) {
        PointMetrics m = synthetic_point(index++, er, rls, 10.0);
        m.point.other_axes["damping"] = damping;
        m.final_state.u_mean += damping;  // the damping levels differ by exactly 1
        points.push_back(m);
      }
  PointMetrics convergence = synthetic_point(index++, 1e2, 1.0, 10.0);
  convergence.point.other_axes = {{"damping", 0.0}, {"mesh_scale", 0.5}};
  convergence.final_state.u_mean = 99.0;  // would spoil the damping-0 fit if it were in it
  points.push_back(convergence);

  const StudyFits fits = fit_study(points);
  CHECK(fits.axis_groups() == std::vector<AxisLevels>{{{"damping", 0.0}}, {{"damping", 1.0}}});
  CHECK(fits.fits.size() == 2 * kAllMetrics.size());
  CHECK(fits.find(Metric::final_u_mean, 10.0) == nullptr);  // no group without the axis
  const MetricFit* d0 = fits.find(Metric::final_u_mean, 10.0, {{"damping", 0.0}});
  const MetricFit* d1 = fits.find(Metric::final_u_mean, 10.0, {{"damping", 1.0}});
  REQUIRE(d0);
  REQUIRE(d1);
  CHECK(d0->fit.samples.size() == 12);
  CHECK(d0->fit.surface(2.0, 1.0) == Approx(0.1 * (0.6 - 0.2)).margin(1e-10));
  CHECK(d1->fit.surface(2.0, 1.0) == Approx(1.0 + 0.1 * (0.6 - 0.2)).margin(1e-10));
  CHECK(fits.kinetic_energy_levels({{"damping", 1.0}}) == std::vector<double>{10.0});
  CHECK(axes_text({{"damping", 1.0}, {"penalty", 0.5}}) == "damping=1, penalty=0.5");
}
