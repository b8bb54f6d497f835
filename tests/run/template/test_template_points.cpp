// A grid over a scene (run/template/template_points.hpp): each point's scene is the template
// with the point's values at their paths; its ER, RLS and KE are that scene's groups, checked
// here against their closed forms; the rigid model makes the named body rigid; every path,
// value and body that does not exist is refused before any run, naming the grid file's line.
#include <fmt/format.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "config/config_error.hpp"
#include "run/scene/scene_file.hpp"
#include "run/template/template_points.hpp"
#include "study/fit/study_fits.hpp"
#include "study/grid/grid_expand.hpp"
#include "study/grid/grid_file.hpp"
#include "tests/support/scene_fixtures.hpp"
#include "tests/support/temp_dir.hpp"

using namespace ccm;
using namespace ccm::study;
using Catch::Contains;

namespace {

// Lines 1-6 of every grid below; the axes start on line 7.
const char* const kTemplateHead = R"(title = "striker over a base"
[template]
scene = "strike.toml"
rigid = ["striker"]

[axes]
)";

GridSpec template_grid(const test::TempDir& dir, const std::string& axes) {
  dir.write("strike.toml", test::kStrikeScene);
  const auto grid = dir.write("grid.toml", kTemplateHead + axes);
  return parse_grid_file(grid);
}

std::string refusal(const test::TempDir& dir, const std::string& axes) {
  try {
    template_grid_points(template_grid(dir, axes));
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("template points: ER, RLS and KE are each point's groups", "[template]") {
  test::TempDir dir;
  const GridSpec spec = template_grid(dir,
                                      "\"bodies.striker.material.E\" = [1e6, 1e8]\n"
                                      "\"bodies.striker.initial_velocity[2]\" = [-1.0, -2.0]\n");
  const std::vector<GridPoint> points = template_grid_points(spec);
  REQUIRE(points.size() == 4);
  // The striker is a 6 x 6 x 4 mm box of 1000 kg/m^3 (its tet mesh has the box's volume); the
  // base's largest extent is 10 mm. RLS = (6 V / pi)^(1/3) / L_A, KE = m v^2 / 2.
  const double V = 0.006 * 0.006 * 0.004, m = 1000.0 * V;
  const double rls = std::cbrt(6.0 * V / std::numbers::pi) / 0.01;
  for (const GridPoint& p : points) {
    const double E = p.other_axes.at("axes.bodies.striker.material.E");
    const double v = p.other_axes.at("axes.bodies.striker.initial_velocity[2]");
    CHECK(p.modulus_ratio == E / 1e5);
    CHECK(p.length_ratio == Approx(rls).epsilon(1e-12));
    CHECK(p.kinetic_energy == Approx(0.5 * m * v * v).epsilon(1e-12));
  }
  // The coordinates reach the fits through ER, RLS and KE: they select no fit of their own.
  CHECK(fit_axes(points[0]).empty());
}

TEST_CASE("template points: the point's scene, and the rigid model's", "[template]") {
  test::TempDir dir;
  const GridSpec spec = template_grid(dir,
                                      "\"bodies.striker.material.E\" = [1e6, 1e8]\n"
                                      "[levels]\n\"bodies.base.material.nu\" = [0.3, 0.45]\n");
  const std::vector<GridPoint> points = template_grid_points(spec);
  REQUIRE(points.size() == 4);
  const GridPoint& p = points[3];  // E 1e8, nu 0.45 (the last axis fastest)
  CHECK(p.other_axes.at("axes.bodies.striker.material.E") == 1e8);
  CHECK(p.other_axes.at("levels.bodies.base.material.nu") == 0.45);
  CHECK(fit_axes(p) == AxisLevels{{"levels.bodies.base.material.nu", 0.45}});

  const Scene ccm = template_point_scene(spec, p, ImpactModel::ccm);
  const Scene rigid = template_point_scene(spec, p, ImpactModel::rigid);
  REQUIRE(ccm.bodies.size() == 2);
  CHECK(ccm.bodies[0].material.nu == 0.45);
  CHECK(ccm.bodies[1].material.E == 1e8);
  CHECK_FALSE(ccm.bodies[1].rigid);
  CHECK(rigid.bodies[1].rigid);
  CHECK(rigid.bodies[1].initial_velocity.z() == -1.0);
  CHECK(template_artifact(spec, rigid) == "base");
  CHECK(template_point_name(spec, p, ImpactModel::rigid) == dir.path / "strike.point3.rigid.toml");
  // The two models are two runs; the same point asked twice is one.
  CHECK(template_run_identity(spec, p, ImpactModel::ccm) !=
        template_run_identity(spec, p, ImpactModel::rigid));
  CHECK(template_run_identity(spec, p, ImpactModel::ccm) ==
        template_run_identity(spec, p, ImpactModel::ccm));
}

TEST_CASE("template points: a path, a value or a body that does not exist is refused",
          "[template]") {
  test::TempDir dir;
  const std::string path = refusal(dir, "\"bodies.strikr.material.E\" = [1e6]\n");
  CHECK_THAT(path, Contains("grid.toml:7: axes.\"bodies.strikr.material.E\": no number at this "
                            "path of the scene (did you mean \"bodies.striker.material.E\"?)"));
  const std::string value = refusal(dir, "\"bodies.striker.material.E\" = [1e6, -5.0]\n");
  CHECK_THAT(value, Contains("grid.toml:7: axes.\"bodies.striker.material.E\": the value -5 "
                             "gives a scene ccm refuses") &&
                        Contains("material.E"));
  const std::string level = refusal(
      dir,
      "\"bodies.striker.material.E\" = [1e6]\n[levels]\n\"bodies.base.material.nu\" = [0.7]\n");
  CHECK_THAT(level, Contains("grid.toml:9: levels.\"bodies.base.material.nu\": the value 0.7"));

  dir.write("strike.toml", test::kStrikeScene);
  const auto body = dir.write("body.toml",
                              "[template]\nscene = \"strike.toml\"\nrigid = [\"strikr\"]\n[axes]\n"
                              "\"bodies.base.material.E\" = [1e5]\n");
  CHECK_THROWS_WITH(template_grid_points(parse_grid_file(body)),
                    Contains("body.toml:3: template.rigid") && Contains("did you mean 'striker'?"));
  const auto both =
      dir.write("both.toml",
                "[template]\nscene = \"strike.toml\"\nrigid = [\"striker\", \"base\"]\n"
                "[axes]\n\"bodies.base.material.E\" = [1e5]\n");
  CHECK_THROWS_WITH(template_grid_points(parse_grid_file(both)),
                    Contains("both.toml:3: template.rigid: point 0: the groups need one impactor"));
  std::string whole = test::kStrikeScene;
  whole.replace(whole.find("end = 2e-3\n"), 11, "end = 2e-2\nend_after_separation = 1e-3\n");
  dir.write("whole.toml", whole);
  const auto impact =
      dir.write("impact.toml",
                "[template]\nscene = \"whole.toml\"\nrigid = [\"striker\"]\n[axes]\n"
                "\"bodies.base.material.E\" = [1e5]\n");
  // A template scene that ends after separation makes a whole-impact study (docs/grid-file.md):
  // both models' scenes keep the criterion.
  const auto impact_spec = parse_grid_file(impact);
  const auto impact_points = template_grid_points(impact_spec);
  REQUIRE(impact_points.size() == 1);
  for (auto model : {ImpactModel::ccm, ImpactModel::rigid})
    CHECK(template_point_scene(impact_spec, impact_points[0], model).time.end_after_separation ==
          1e-3);
  const auto missing =
      dir.write("missing.toml",
                "[template]\nscene = \"nowhere.toml\"\nrigid = [\"striker\"]\n[axes]\n"
                "\"bodies.base.material.E\" = [1e5]\n");
  CHECK_THROWS_WITH(template_grid_points(parse_grid_file(missing)),
                    Contains("missing.toml:2: template.scene") && Contains("nowhere.toml"));
}

// The studies in the repository (scenes/studies/): each is a grid over a scene whose points pass
// the checks (those at the ends of its first axis), and whose ER is its first path's value (the
// impactor's E) over the E the template scene gives its artifact.
TEST_CASE("template points: every study in scenes/studies is valid, its ER E_I / E_A",
          "[template]") {
  const std::filesystem::path folder = std::filesystem::path(CCM_SOURCE_DIR) / "scenes" / "studies";
  int studies = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().extension() != ".toml") continue;
    INFO(entry.path().string());
    GridSpec spec = parse_grid_file(entry.path());
    REQUIRE(spec.scene_template);
    REQUIRE(grid_size(spec) >= 6);
    // Its first axis's ends, the other axes at their first value: 2 points to mesh, not all.
    for (TemplateAxis& a : spec.scene_template->axes)
      a.values = &a == &spec.scene_template->axes.front()
                     ? std::vector<double>{a.values.front(), a.values.back()}
                     : std::vector<double>{a.values.front()};
    for (TemplateAxis& a : spec.scene_template->levels) a.values = {a.values.front()};
    const std::string axis =
        std::string(kTemplateAxisPrefix) + spec.scene_template->axes.front().path;
    const std::vector<GridPoint> points = template_grid_points(spec);
    REQUIRE(points.size() == 2);
    const Scene scene = parse_scene_file(spec.scene_template->scene);
    const std::string artifact = template_artifact(spec, scene);
    double e_artifact = 0.0;
    for (const BodySpec& b : scene.bodies)
      if (b.name == artifact) e_artifact = b.material.E;
    for (const GridPoint& p : points)
      CHECK(p.modulus_ratio == Approx(p.other_axes.at(axis) / e_artifact).epsilon(1e-11));
    ++studies;
  }
  CHECK(studies >= 3);
}
