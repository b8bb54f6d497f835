// Grid files: the thesis grid reads as Table 2.2; bad input is rejected with
// "<file>:<line>: <key>: <problem>".
#include <fmt/format.h>

#include <catch2/catch.hpp>
#include <string>

#include "study/grid/grid_file.hpp"
#include "tests/study/grid/grid_fixtures.hpp"

using Catch::Contains;
using ccm::test::grid_error_of;
using ccm::test::kSmallGrid;
using ccm::test::small_grid_plus;
using ccm::test::small_grid_with;
using namespace ccm::study;

TEST_CASE("the thesis grid file is Table 2.2 with the fixed parameters of section 2.8", "[grid]") {
  const GridSpec g = parse_grid_file(CCM_SOURCE_DIR "/scenes/grids/thesis.toml");
  CHECK(g.modulus_ratios == std::vector<double>{1.0, 1e2, 1e4, 1e6});
  CHECK(g.length_ratios == std::vector<double>{0.5, 1.0, 1.5});
  CHECK(g.kinetic_energies == std::vector<double>{10.0, 50.0, 100.0});
  CHECK(g.other_axes.empty());
  CHECK(g.artifact.E == 1000.0);
  CHECK(g.artifact.rho == 1000.0);
  CHECK(g.impactor.rho == 1000.0);
  CHECK(g.artifact.nu == 0.49);
  CHECK(g.impactor.nu == 0.49);
  CHECK(g.time.contact_time == 0.1);
  CHECK(g.time.end == 0.15);
  CHECK(g.contact.penalty == 1e6);
  CHECK(g.contact.damping == 1.0);
  CHECK(g.contact.restitution == 1.0);
  CHECK(g.artifact.contact_mesh_size == 0.03);
  CHECK(g.impactor.contact_mesh_size == 0.04);
  CHECK(g.convergence.points.size() == 8);
  CHECK(g.convergence.mesh_scales.size() == 3);
}

TEST_CASE("a small grid file parses with its defaults", "[grid]") {
  const GridSpec g = parse_grid(kSmallGrid, "g.toml");
  CHECK(g.source == "g.toml");
  CHECK(g.artifact.support == ArtifactSupport::base);
  CHECK(g.time.dt_safety == 0.9);
  CHECK(g.time.max_steps == 0);
  CHECK(g.contact.restitution == 0.0);
  CHECK(g.convergence.points.empty());
}

TEST_CASE("grid file errors name the file, the line and the key", "[grid]") {
  SECTION("unknown key, with the allowed ones") {
    CHECK_THAT(grid_error_of(small_grid_with("rho = 1000.0\nmesh_size", "densty = 1.0\nmesh_size")),
               Contains("g.toml:16: artifact.densty: unknown key 'densty'") &&
                   Contains("allowed: length, thickness"));
  }
  SECTION("unknown axis") {
    CHECK_THAT(grid_error_of(small_grid_with("KE = [10.0, 100.0]", "KE = [10.0]\nmu = [0.1]")),
               Contains("g.toml:5: axes.mu: unknown key 'mu'"));
  }
  SECTION("wrong type") {
    CHECK_THAT(grid_error_of(small_grid_with("end = 0.15", "end = \"long\"")),
               Contains("g.toml:8: time.end: expected a number, got a string"));
    CHECK_THAT(grid_error_of(small_grid_with("ER = [1.0, 100.0]", "ER = 1.0")),
               Contains("g.toml:2: axes.ER: expected an array of numbers, got a float"));
    CHECK_THAT(grid_error_of(small_grid_with("RLS = [0.5, 1.0, 1.5]", "RLS = [0.5, \"x\"]")),
               Contains("g.toml:3: axes.RLS[1]: expected a number, got a string"));
  }
  SECTION("out of range") {
    CHECK_THAT(grid_error_of(small_grid_with("nu = 0.49", "nu = 0.5")),
               Contains("g.toml:15: artifact.nu: must lie in (-1, 0.5) (got 0.5)"));
    CHECK_THAT(grid_error_of(small_grid_with("KE = [10.0, 100.0]", "KE = [10.0, -1.0]")),
               Contains("g.toml:4: axes.KE: [1] must be > 0 (got -1)"));
    CHECK_THAT(grid_error_of(small_grid_with("mesh_size_ratio = 0.2", "mesh_size_ratio = 0.6")),
               Contains("g.toml:22: impactor.mesh_size_ratio: must lie in (0, 0.5] (got 0.6)"));
    CHECK_THAT(grid_error_of(small_grid_with("contact_time = 0.1", "contact_time = 0.2")),
               Contains("g.toml:7: time.contact_time: must be < end = 0.15 (got 0.2)"));
    CHECK_THAT(grid_error_of(small_grid_with("ER = [1.0, 100.0]", "ER = [1.0, 1.0]")),
               Contains("g.toml:2: axes.ER: [1] repeats the value 1"));
  }
  SECTION("out of range: time step safety and contact parameters") {
    CHECK_THAT(grid_error_of(small_grid_with("output_interval = 1e-3",
                                             "output_interval = 1e-3\ndt_safety = 0.0")),
               Contains("g.toml:10: time.dt_safety: must lie in (0, 1] (got 0)"));
    CHECK_THAT(grid_error_of(small_grid_with("output_interval = 1e-3",
                                             "output_interval = 1e-3\nend_after_separation = 0.2")),
               Contains("g.toml:10: time.end_after_separation: must lie in [0, end = 0.15) (got "
                        "0.2)"));
    CHECK_THAT(grid_error_of(small_grid_with("output_interval = 1e-3",
                                             "output_interval = 1e-3\nend_after_separation = -1")),
               Contains("g.toml:10: time.end_after_separation: must lie in [0, end = 0.15)"));
    CHECK_THAT(grid_error_of(small_grid_plus("\n[contact]\nrestitution = 2.0\n")),
               Contains("g.toml:25: contact.restitution: must lie in [0, 1] (got 2)"));
    CHECK_THAT(
        grid_error_of(small_grid_with("KE = [10.0, 100.0]", "KE = [10.0]\nfriction = [-0.1]")),
        Contains("g.toml:5: axes.friction: [0] must be >= 0 (got -0.1)"));
  }
  SECTION("missing key or table: the line of the enclosing table") {
    CHECK_THAT(grid_error_of(small_grid_with("E = 1000.0\n", "")),
               Contains("g.toml:11: artifact.E: required key is missing"));
    CHECK_THAT(grid_error_of(small_grid_with("[impactor]", "[impactorr]")),
               Contains("g.toml:19: impactorr: unknown key 'impactorr'"));
  }
  SECTION("support and convergence") {
    CHECK_THAT(
        grid_error_of(small_grid_with("mesh_size = 0.1", "mesh_size = 0.1\nsupport = \"wall\"")),
        Contains("g.toml:18: artifact.support: must be \"base\" or \"edges\""));
    const std::string four_scales = small_grid_plus(
        "\n[convergence]\npoints = [{ ER = 1.0, RLS = 0.5, KE = 10.0 }]\n"
        "mesh_scales = [1.0, 0.8, 0.6, 0.4]\n");
    CHECK_THAT(grid_error_of(four_scales),
               Contains("g.toml:26: convergence.mesh_scales: needs 2 or 3 mesh scales (got 4)"));
    const std::string bad_point = small_grid_plus(
        "\n[convergence]\npoints = [{ ER = 1.0, RLS = 0.5 }]\nmesh_scales = [1.0, 0.5]\n");
    CHECK_THAT(grid_error_of(bad_point),
               Contains("g.toml:25: convergence.points[0].KE: required key is missing"));
  }
  SECTION("TOML syntax error") {
    CHECK_THAT(grid_error_of(small_grid_with("end = 0.15", "end = = 0.15")),
               Contains("g.toml:8: TOML syntax error"));
  }
  SECTION("a file that does not exist") {
    CHECK_THROWS_WITH(parse_grid_file("/nonexistent/grid.toml"),
                      Contains("/nonexistent/grid.toml: no such file"));
  }
}

TEST_CASE("a grid over a scene: its template, its axes by path, and what it refuses", "[grid]") {
  const std::string head =
      "title = \"t\"\n[template]\nscene = \"designs/s.toml\"\nrigid = [\"a\"]\n";
  const std::string axes = "[axes]\n\"bodies.a.material.E\" = [1e6, 1e7]\n\"time.end\" = [0.1]\n";
  const GridSpec g =
      parse_grid(head + axes + "[levels]\n\"contact.friction\" = [0.0, 0.3]\n", "grids/g.toml");
  REQUIRE(g.scene_template);
  const SceneTemplate& t = *g.scene_template;
  CHECK(t.scene == std::filesystem::path("grids/designs/s.toml"));  // beside the grid file
  CHECK(t.rigid == std::vector<std::string>{"a"});
  REQUIRE(t.axes.size() == 2);
  CHECK(t.axes[0].path == "bodies.a.material.E");  // file order
  CHECK(t.axes[0].values == std::vector<double>{1e6, 1e7});
  CHECK(t.axes[0].line == 6);
  REQUIRE(t.levels.size() == 1);
  CHECK(t.levels[0].path == "contact.friction");
  CHECK(t.scene_line == 3);
  CHECK(t.rigid_line == 4);

  CHECK_THAT(grid_error_of(head + axes + "[time]\nend = 1.0\n"),
             Contains("g.toml:8: time: a grid over a scene takes this from its [template] scene"));
  CHECK_THAT(grid_error_of(fmt::format("{}[levels]\n\"a.b\" = [1.0]\n", kSmallGrid)),
             Contains("levels: belongs to a grid over a scene ([template])"));
  CHECK_THAT(grid_error_of("[template]\nscene = \"s.toml\"\nrigid = []\n" + axes),
             Contains("g.toml:3: template.rigid"));
  CHECK_THAT(grid_error_of("[template]\nscene = \"s.toml\"\nrigid = [\"a\", \"a\"]\n" + axes),
             Contains("names \"a\" twice"));
  CHECK_THAT(grid_error_of(head + "[axes]\n\"time.end\" = [0.1, 0.1]\n"),
             Contains("g.toml:6: axes.time.end: [1] repeats the value 0.1"));
  CHECK_THAT(grid_error_of(head), Contains("axes: required table is missing"));
}
