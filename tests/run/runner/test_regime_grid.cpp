// The shipped whole-impact grid over the users' regime (scenes/grids/whole-impacts.toml): what
// the issue asks of it (ER 1-1e4, RLS 0.25-1.5, KE* 1e-4-1e-1, density ratio 1 and about 7,
// whole impacts), read from the file, and every point's two scenes built with the separation
// criterion and the density its point says.
#include <catch2/catch.hpp>
#include <set>

#include "run/runner/study_scene.hpp"
#include "study/grid/grid_expand.hpp"
#include "study/grid/grid_file.hpp"

using namespace ccm;
using namespace ccm::study;

TEST_CASE("the whole-impact grid covers the users' regime", "[grid]") {
  const GridSpec g = parse_grid_file(CCM_SOURCE_DIR "/scenes/grids/whole-impacts.toml");
  REQUIRE(g.time.end_after_separation.has_value());
  const std::vector<GridPoint> points = expand_grid(g);
  REQUIRE(points.size() == 3 * 4 * 4 * 2);
  const double energy_scale = g.artifact.E * g.artifact.length * g.artifact.length *
                              g.artifact.length;  // E_A L_A^3: KE* = KE / that
  double er_lo = 1e300, er_hi = 0, rls_lo = 1e300, rls_hi = 0, ke_lo = 1e300, ke_hi = 0;
  std::set<double> density_ratios;
  for (const GridPoint& p : points) {
    er_lo = std::min(er_lo, p.modulus_ratio), er_hi = std::max(er_hi, p.modulus_ratio);
    rls_lo = std::min(rls_lo, p.length_ratio), rls_hi = std::max(rls_hi, p.length_ratio);
    ke_lo = std::min(ke_lo, p.kinetic_energy / energy_scale);
    ke_hi = std::max(ke_hi, p.kinetic_energy / energy_scale);
    density_ratios.insert(p.other_axes.at("density_ratio"));
  }
  CHECK(er_lo == 1.0);
  CHECK(er_hi == 1e4);
  CHECK(rls_lo == 0.25);
  CHECK(rls_hi == 1.5);
  CHECK(ke_lo == Approx(1e-4));
  CHECK(ke_hi == Approx(1e-1));
  CHECK(density_ratios == std::set<double>{1.0, 7.8});
  for (const GridPoint& p : {points.front(), points.back()})
    for (ImpactModel m : {ImpactModel::ccm, ImpactModel::rigid}) {
      const Scene s = study_scene(g, p, m);
      CHECK(s.time.end_after_separation == g.time.end_after_separation);
      CHECK(s.time.end == g.time.end);
    }
  // The last point is steel (7.8): its meshed sphere's density says so.
  const Scene steel = study_scene(g, points.back(), ImpactModel::ccm);
  bool found = false;
  for (const BodySpec& b : steel.bodies)
    if (b.name == "impactor") found = b.material.rho == 7800.0;
  CHECK(found);
}
