// `ccm compare`'s library (run/compare/): the rigid variant of a scene, the observables checked
// against both runs' columns, and the errors and decision against their closed forms on series
// built by hand.
#include <catch2/catch.hpp>
#include <cmath>

#include "run/compare/rigid_variant.hpp"
#include "run/compare/scene_comparison.hpp"
#include "run/compare/scene_groups.hpp"
#include "run/scene/point_scene.hpp"
#include "run/scene/scene_builder.hpp"
#include "run/scene/scene_file.hpp"
#include "study/grid/grid_expand.hpp"
#include "study/grid/grid_file.hpp"
#include "tests/support/scene_fixtures.hpp"

using Catch::Contains;
using namespace ccm;

namespace {

std::string variant_error_of(const Scene& s, const std::vector<std::string>& names) {
  try {
    with_rigid_bodies(s, names);
  } catch (const RigidVariantError& e) {
    return e.what();
  }
  return "(no error)";
}

// A run with time 0..3 and one column "b.u_max" = values.
ComparedRun run_of(std::vector<double> values, double cpu) {
  ComparedRun r;
  r.columns = {"time", "b.u_max"};
  for (size_t k = 0; k < values.size(); ++k) r.rows.push_back({double(k), values[k]});
  r.step_cpu_seconds = cpu;
  return r;
}

}  // namespace

TEST_CASE("compare: the rigid variant makes the named bodies rigid, a held one fixed",
          "[compare]") {
  const std::string two = test::kTimeToml + test::cube_body_toml("a") + test::cube_body_toml("b") +
                          "[[fixed]]\nbody = \"b\"\nnode_set = \"boundary\"\n";
  const Scene scene = parse_scene(two, "s.toml");
  const Scene v = with_rigid_bodies(scene, {"a", "b"});
  CHECK(v.bodies[0].rigid);
  CHECK(v.bodies[0].motion == RigidMotion::free);
  CHECK(v.bodies[1].rigid);
  CHECK(v.bodies[1].motion == RigidMotion::fixed);  // held by its [[fixed]] table, now gone
  CHECK(v.fixed.empty());
  CHECK(!scene.bodies[0].rigid);  // the scene as written is untouched
  CHECK(default_observables(with_rigid_bodies(scene, {"a"})) ==
        std::vector<std::string>{"b.u_mean", "b.u_max", "b.kinetic_energy"});

  CHECK_THAT(variant_error_of(scene, {"c"}),
             Contains("--rigid c: no body named 'c' in s.toml") && Contains("bodies: a, b"));
  CHECK_THAT(variant_error_of(scene, {"aa"}), Contains("did you mean 'a'?"));
  CHECK_THAT(variant_error_of(scene, {"a", "a"}), Contains("named twice"));
  CHECK_THAT(variant_error_of(v, {"a"}), Contains("rigid in s.toml already"));
  CHECK_THAT(variant_error_of(scene, {}), Contains("at least one body"));
}

TEST_CASE("compare: observables must be columns of both runs", "[compare]") {
  const std::vector<std::string> d = {"time", "b.u_max", "b.u_mean", "pair.work"};
  const std::vector<std::string> r = {"time", "b.u_max", "b.u_mean", "a.x"};
  CHECK_NOTHROW(check_observables({"b.u_max"}, d, r));
  CHECK_THROWS_WITH(check_observables({"b.umax"}, d, r),
                    Contains("--observe b.umax") && Contains("did you mean 'b.u_max'?"));
  CHECK_THROWS_WITH(check_observables({"a.x"}, d, r), Contains("not a history column of both"));
  CHECK_THROWS_WITH(check_observables({}, d, r), Contains("nothing to compare"));
}

TEST_CASE("compare: errors, cost ratio and answer against their closed forms", "[compare]") {
  // Deformable 0, 1, 2, 2; rigid 0, 1, 2, 2.2: final-state error |2 - 2.2| / 2.2 (eq. 2.37);
  // cumulative: <(c - r)^2> / ((<c> + <r>) / 2) with trapezoids over t = 0..3.
  const ComparedRun d = run_of({0.0, 1.0, 2.0, 2.0}, 6.0), r = run_of({0.0, 1.0, 2.0, 2.2}, 2.0);
  const ComparisonOutcome o = compare_runs(d, r, {"b.u_max"}, 0.1);
  REQUIRE(o.unusable.empty());
  REQUIRE(o.errors.size() == 1);
  CHECK(o.errors[0].final_state == Approx(0.2 / 2.2).epsilon(1e-14));
  const double sq = (0.5 * 0.04) / 3.0;  // the trapezoid of (c - r)^2: 0, 0, 0, 0.04
  const double mean_c = (0.5 + 1.5 + 2.0) / 3.0, mean_r = (0.5 + 1.5 + 2.1) / 3.0;
  CHECK(o.errors[0].cumulative == Approx(sq / ((mean_c + mean_r) / 2.0)).epsilon(1e-14));
  CHECK(o.cost_ratio == 3.0);
  CHECK(o.decision.model == study::ImpactModel::rigid);  // 0.091 <= 0.1 and 3 > 1
  CHECK(compare_runs(d, r, {"b.u_max"}, 0.05).decision.model == study::ImpactModel::ccm);
  CHECK(compare_runs(d, run_of({0.0, 1.0, 2.0, 2.2}, 7.0), {"b.u_max"}, 0.1).decision.model ==
        study::ImpactModel::ccm);  // rigid costs more

  ComparedRun unstable = r;
  unstable.verdict = "unstable";
  unstable.reason = "energy";
  CHECK_THAT(compare_runs(d, unstable, {"b.u_max"}, 0.1).unusable,
             Contains("the rigid run is unstable: energy"));
  CHECK_THAT(compare_runs(d, run_of({0.0, 1.0}, 1.0), {"b.u_max"}, 0.1).unusable,
             Contains("4 and 2 samples"));
}

TEST_CASE("compare: a grid point's own scene gives back the point's ER, RLS and KE",
          "[compare][grid]") {
  // The thesis's sphere on its plate, at a point of a grid: the groups computed from the scene
  // (impactor = the sphere made rigid, artifact = the plate) are the point's, to round-off: D_I
  // from the sphere's mass at its density, L_A the plate's side (its box corners are nodes), KE
  // from the mass and speed the point set.
  const study::GridSpec g =
      study::parse_grid_file(std::string(CCM_SOURCE_DIR) + "/scenes/grids/default.toml");
  const study::GridPoint p = study::expand_grid(g).front();
  const Scene scene = study::point_scene(g, p, study::ImpactModel::ccm);
  const Model model = build_model(scene);
  const GroupsOrReason r = scene_groups(scene, model, {study::kImpactorName}, std::nullopt);
  REQUIRE(r.groups);
  CHECK(r.groups->artifact == study::kArtifactBody);
  CHECK(r.groups->modulus_ratio == Approx(p.modulus_ratio).epsilon(1e-12));
  CHECK(r.groups->length_ratio == Approx(p.length_ratio).epsilon(1e-12));
  CHECK(r.groups->kinetic_energy == Approx(p.kinetic_energy).epsilon(1e-12));
  CHECK(r.groups->kinetic_energy_star ==
        Approx(p.kinetic_energy / (g.artifact.E * std::pow(g.artifact.length, 3))).epsilon(1e-12));
  CHECK(r.groups->density_ratio == 1.0);
  // Without one impactor and one artifact there are no groups, and it says why.
  CHECK_THAT(scene_groups(scene, model, {"a", "b"}, std::nullopt).reason, Contains("one impactor"));
}
