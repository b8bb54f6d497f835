// The scene of a grid point: sphere diameter D_I = RLS L_A, E_I = ER E_A, speed from KE and the
// sphere's mass, contact starting at t_c (gap / speed = t_c); both models share the artifact.
#include <fmt/format.h>

#include <catch2/catch.hpp>
#include <numbers>
#include <string>
#include <variant>

#include "records/content_hash.hpp"
#include "run/scene/point_scene.hpp"
#include "study/grid/grid_expand.hpp"
#include "study/grid/grid_file.hpp"
#include "study/grid/point_parameters.hpp"
#include "tests/study/grid/grid_fixtures.hpp"
#include "tests/support/tolerance.hpp"

using ccm::test::grid_error_of;
using ccm::test::kSmallGrid;
using ccm::test::relative_error;
using ccm::test::small_grid_with;
using namespace ccm;
using namespace ccm::study;

namespace {

GridPoint point(double er, double rls, double ke) {
  GridPoint p;
  p.modulus_ratio = er;
  p.length_ratio = rls;
  p.kinetic_energy = ke;
  return p;
}

const BodySpec& body_named(const Scene& s, const std::string& name) {
  for (const BodySpec& b : s.bodies)
    if (b.name == name) return b;
  FAIL("no body " << name);
  throw;
}

// Parser round trip of a double: the scene text writes shortest round-trip numbers, so the
// values come back bit-identical; 1e-15 only allows for the products computed on the way.
constexpr double kExact = 1e-15;

}  // namespace

TEST_CASE("ccm scene of a point: meshed sphere of D_I = RLS L_A, E_I = ER E_A, v from KE",
          "[grid]") {
  const GridSpec g = parse_grid(kSmallGrid, "g.toml");
  const Scene s = point_scene(g, point(1e2, 0.5, 100.0), ImpactModel::ccm);
  REQUIRE(s.bodies.size() == 2);
  const BodySpec& artifact = body_named(s, "artifact");
  const BodySpec& impactor = body_named(s, "impactor");
  CHECK(artifact.material.E == 1000.0);
  CHECK(artifact.material.nu == 0.49);
  CHECK(artifact.material.rho == 1000.0);
  CHECK(artifact.geometry.primitive.size == Vec3(1.0, 1.0, 0.25));
  CHECK(artifact.geometry.primitive.mesh_size == 0.1);
  CHECK(impactor.geometry.shape == Shape::sphere);
  CHECK(impactor.geometry.primitive.radius == 0.25);                            // D_I = 0.5 x 1 m
  CHECK(impactor.geometry.primitive.mesh_size == Approx(0.1).epsilon(kExact));  // 0.2 D_I
  CHECK(impactor.material.E == Approx(1e5).epsilon(kExact));                    // 100 x 1000 Pa
  CHECK(impactor.material.nu == 0.49);
  CHECK(impactor.material.rho == 1000.0);
  // m = 1000 pi 0.5^3 / 6 = 65.4498 kg; v = sqrt(2 x 100 / m) = 1.748077 m/s (by hand).
  const Vec3 v = impactor.initial_velocity;
  CHECK(v.x() == 0.0);
  CHECK(v.y() == 0.0);
  CHECK(relative_error(-v.z(), 1.748077) < 1e-6);
  // Lowest point of the sphere above the top face z = 0.25, reached after t_c = 0.1 s.
  const Vec3 c = impactor.placement.translation;
  CHECK(c.x() == 0.5);
  CHECK(c.y() == 0.5);
  const double gap = c.z() - 0.25 - 0.25;
  CHECK(relative_error(gap / -v.z(), 0.1) < 1e-12);
  CHECK(s.contacts.at(0).kind == ContactKind::dcr);
  CHECK(s.contacts.at(0).surfaces == std::vector<std::string>{"impactor", "artifact"});
  CHECK(s.time.end == 0.15);
  CHECK(s.time.output_interval == 1e-3);
  REQUIRE(s.fixed.size() == 1);  // support "base": the bottom face
  const auto& plane = std::get<PlaneSpec>(s.fixed[0].selection);
  CHECK(plane.normal == Vec3(0, 0, 1));
  CHECK(plane.point.z() == 0.0);
}

TEST_CASE("rigid scene of a point: the same artifact, an analytic sphere with the same motion",
          "[grid]") {
  const GridSpec g = parse_grid(kSmallGrid, "g.toml");
  const GridPoint p = point(1e6, 1.5, 10.0);
  const Scene ccm_scene = point_scene(g, p, ImpactModel::ccm);
  const Scene rigid = point_scene(g, p, ImpactModel::rigid);
  REQUIRE(rigid.bodies.size() == 1);
  const BodySpec& a_rigid = rigid.bodies[0];
  const BodySpec& a_ccm = body_named(ccm_scene, "artifact");
  CHECK(a_rigid.name == "artifact");
  CHECK(a_rigid.material.E == a_ccm.material.E);
  CHECK(a_rigid.geometry.primitive.size == a_ccm.geometry.primitive.size);
  CHECK(a_rigid.geometry.primitive.mesh_size == a_ccm.geometry.primitive.mesh_size);
  REQUIRE(rigid.contacts.at(0).kind == ContactKind::rigid_penalty);
  CHECK(rigid.contacts.at(0).body == "artifact");
  CHECK(rigid.contacts.at(0).penalty == 1e6);
  const RigidSphereSpec& sphere = rigid.contacts.at(0).sphere;
  const BodySpec& impactor = body_named(ccm_scene, "impactor");
  CHECK(sphere.radius == 0.75);  // D_I = 1.5 x 1 m
  CHECK(sphere.center == impactor.placement.translation);
  CHECK(sphere.velocity == impactor.initial_velocity);
  // m = 1000 pi 1.5^3 / 6 = 1767.146 kg (mass from density); v = sqrt(20 / m) = 0.1063846 m/s.
  CHECK(relative_error(sphere.mass, 1767.146) < 1e-6);
  CHECK(relative_error(-sphere.velocity.z(), 0.1063846) < 1e-6);
  CHECK(relative_error(0.5 * sphere.mass * sphere.velocity.squaredNorm(), 10.0) < 1e-12);
  CHECK(relative_error((sphere.center.z() - 0.75 - 0.25) / -sphere.velocity.z(), 0.1) < 1e-12);
  CHECK(rigid.time.output_interval == ccm_scene.time.output_interval);
  CHECK(rigid.time.end == ccm_scene.time.end);
}

TEST_CASE("other axes and support reach the scene", "[grid]") {
  const GridSpec g = parse_grid(
      small_grid_with("mesh_size = 0.1", "mesh_size = 0.1\nsupport = \"edges\""), "g.toml");
  GridPoint p = point(1.0, 1.0, 50.0);
  p.other_axes = {{"nu", 0.3}, {"mesh_scale", 0.5}, {"restitution", 0.25}};
  const Scene s = point_scene(g, p, ImpactModel::ccm);
  CHECK(body_named(s, "artifact").material.nu == 0.3);
  CHECK(body_named(s, "impactor").material.nu == 0.3);
  CHECK(body_named(s, "artifact").geometry.primitive.mesh_size == 0.05);
  CHECK(body_named(s, "impactor").geometry.primitive.mesh_size == Approx(0.1).epsilon(kExact));
  CHECK(s.contacts.at(0).restitution == 0.25);
  REQUIRE(s.fixed.size() == 2);  // support "edges": x = 0 and x = L_A
  CHECK(std::get<PlaneSpec>(s.fixed[1].selection).point.x() == 1.0);
  CHECK(std::get<PlaneSpec>(s.fixed[1].selection).normal == Vec3(1, 0, 0));
}

TEST_CASE("scene text and its hash (the run-reuse key): deterministic, independent of the index",
          "[grid]") {
  const GridSpec g = parse_grid(kSmallGrid, "g.toml");
  GridPoint p = point(1e2, 1.0, 50.0);
  const std::string text = point_scene_text(g, p, ImpactModel::ccm);
  const std::string key = fnv1a64(point_scene_text(g, p, ImpactModel::ccm));
  CHECK(point_scene_text(g, p, ImpactModel::ccm) == text);
  CHECK(key.size() == 16);
  p.index = 17;
  CHECK(point_scene_text(g, p, ImpactModel::ccm) == text);
  CHECK(fnv1a64(point_scene_text(g, p, ImpactModel::ccm)) == key);
  CHECK(point_scene_name(g, p, ImpactModel::rigid) == "g.point17.rigid.toml");
  CHECK(fnv1a64(point_scene_text(g, p, ImpactModel::rigid)) != key);
  GridSpec stiffer = g;
  stiffer.artifact.E = 2000.0;  // a fixed parameter
  CHECK(fnv1a64(point_scene_text(stiffer, p, ImpactModel::ccm)) != key);
  p.kinetic_energy = 50.000000000001;
  CHECK(fnv1a64(point_scene_text(g, p, ImpactModel::ccm)) != key);
  // FNV-1a 64 reference values (the published test vectors).
  CHECK(fnv1a64("") == "cbf29ce484222325");
  CHECK(fnv1a64("a") == "af63dc4c8601ec8c");
}

TEST_CASE("point parameters: closed forms of the impact", "[grid]") {
  const GridSpec g = parse_grid(kSmallGrid, "g.toml");
  const PointParameters p = point_parameters(g, point(1e4, 1.0, 50.0));
  CHECK(p.impactor_diameter == 1.0);
  CHECK(p.impactor_E == 1e7);
  CHECK(relative_error(p.impactor_mass, 523.5988) < 1e-6);  // 1000 pi / 6
  CHECK(relative_error(0.5 * p.impactor_mass * p.impact_speed * p.impact_speed, 50.0) < 1e-12);
  CHECK(relative_error(p.gap, p.impact_speed * 0.1) < 1e-15);
  CHECK(axis_value_problem("restitution", 1.5) == "must lie in [0, 1] (got 1.5)");
  CHECK(axis_value_problem("K", 1.0) == "unknown grid axis 'K'");
  CHECK(axis_value_problem("friction", 0.0).empty());
  // A density_ratio axis sets rho_I = ratio x rho_A: the mass, the speed at the same KE, and the
  // density written into both models' scenes.
  GridPoint steel = point(1e4, 1.0, 50.0);
  steel.other_axes["density_ratio"] = 7.8;
  const PointParameters q = point_parameters(g, steel);
  CHECK(q.impactor_rho == 7800.0);
  CHECK(relative_error(q.impactor_mass, 7.8 * p.impactor_mass) < 1e-14);
  CHECK(relative_error(q.impact_speed, p.impact_speed / std::sqrt(7.8)) < 1e-14);
  CHECK_THAT(point_scene_text(g, steel, ImpactModel::ccm), Catch::Contains("rho = 7800"));
  CHECK_THAT(point_scene_text(g, steel, ImpactModel::rigid), Catch::Contains("7800"));
  CHECK(axis_value_problem("density_ratio", 0.0) == "must be > 0 (got 0)");
}

TEST_CASE("contact zones, the sphere's mass and the penalty's damping reach the scenes", "[grid]") {
  std::string text = small_grid_with(
      "mesh_size = 0.1\n", "mesh_size = 0.1\ncontact_mesh_size = 0.04\ncontact_radius = 0.25\n");
  text += "contact_mesh_size = 0.03\ncontact_radius = 0.2\n\n[contact]\ndamping = 1.0\n";
  const GridSpec g = parse_grid(text, "g.toml");  // the [impactor] table ends kSmallGrid
  GridPoint p = point(1e4, 1.5, 100.0);
  const Scene s = point_scene(g, p, ImpactModel::ccm);
  const auto& plate = body_named(s, "artifact").geometry.primitive;
  REQUIRE(plate.refinement);
  CHECK(plate.refinement->center == Vec3(0.5, 0.5, 0.25));  // the middle of the top face
  CHECK(plate.refinement->radius == 0.25);
  CHECK(plate.refinement->mesh_size == 0.04);
  const BodySpec& ball = body_named(s, "impactor");
  REQUIRE(ball.geometry.primitive.refinement);
  CHECK(ball.geometry.primitive.refinement->center == Vec3(0.0, 0.0, -0.75));  // lowest point
  CHECK(ball.geometry.primitive.refinement->mesh_size == 0.03);
  REQUIRE(ball.mass);
  CHECK(relative_error(*ball.mass, 1000.0 * std::numbers::pi * 1.5 * 1.5 * 1.5 / 6.0) < 1e-15);
  const Scene rigid = point_scene(g, p, ImpactModel::rigid);
  CHECK(rigid.contacts.at(0).damping == 1.0);
  REQUIRE(body_named(rigid, "artifact").geometry.primitive.refinement);
  // A mesh scale refines the zones too; a zone never comes out coarser than its body.
  p.other_axes = {{"mesh_scale", 0.5}};
  const Scene fine = point_scene(g, p, ImpactModel::ccm);
  CHECK(body_named(fine, "artifact").geometry.primitive.refinement->mesh_size == 0.02);
  const GridPoint small = point(1.0, 0.5, 10.0);  // D_I / 5 = 0.1 m > 0.03 m: kept at 0.03
  CHECK(body_named(point_scene(g, small, ImpactModel::ccm), "impactor")
            .geometry.primitive.refinement->mesh_size == 0.03);
}

TEST_CASE("contact zone keys: both or neither, never coarser than the body", "[grid]") {
  CHECK_THAT(grid_error_of(small_grid_with("mesh_size = 0.1\n",
                                           "mesh_size = 0.1\ncontact_mesh_size = 0.04\n")),
             Catch::Contains("artifact.contact_radius: contact_mesh_size and contact_radius are "
                             "given together or not at all"));
  CHECK_THAT(
      grid_error_of(small_grid_with(
          "mesh_size = 0.1\n", "mesh_size = 0.1\ncontact_mesh_size = 0.2\ncontact_radius = 0.3\n")),
      Catch::Contains("artifact.contact_mesh_size: must not exceed mesh_size = 0.1 (got 0.2)"));
  CHECK_THAT(grid_error_of(small_grid_with("mesh_size_ratio = 0.2\n",
                                           "mesh_size_ratio = 0.2\ncontact_radius = -1.0\n"
                                           "contact_mesh_size = 0.01\n")),
             Catch::Contains("impactor.contact_radius: must be > 0"));
}

TEST_CASE("the rigid model's penalty mode: [contact] keys and the penalty_scale axis",
          "[grid][element_penalty]") {
  const GridPoint p = point(1e2, 1.0, 50.0);
  SECTION("[contact] penalty_mode = \"element\" reaches the rigid scene") {
    const GridSpec g =
        parse_grid(fmt::format("{}{}", kSmallGrid,
                               "\n[contact]\npenalty_mode = \"element\"\npenalty_scale = 0.2\n"),
                   "g.toml");
    CHECK(g.contact.penalty_mode == PenaltyMode::element);
    CHECK(g.contact.penalty_scale == 0.2);
    const Scene rigid = point_scene(g, p, ImpactModel::rigid);
    CHECK(rigid.contacts.at(0).penalty_mode == PenaltyMode::element);
    CHECK(rigid.contacts.at(0).penalty_scale == 0.2);
    CHECK_THAT(point_scene_text(g, p, ImpactModel::rigid),
               Catch::Contains("penalty_mode = \"element\"\npenalty_scale = 0.2\n"));
  }
  SECTION("per point (the default): the scene text has no mode key, as before") {
    const GridSpec g = parse_grid(kSmallGrid, "g.toml");
    CHECK(g.contact.penalty_mode == PenaltyMode::per_point);
    const std::string text = point_scene_text(g, p, ImpactModel::rigid);
    CHECK_THAT(text, Catch::Contains("penalty = 1000000.0\ndamping = 0.0\n"));
    CHECK(text.find("penalty_mode") == std::string::npos);
  }
  SECTION("the penalty_scale axis: 0 is the per-point K_P, > 0 the element mode") {
    const GridSpec g = parse_grid(
        small_grid_with("KE = [10.0, 100.0]", "KE = [10.0]\npenalty_scale = [0.0, 0.1]") +
            "\n[contact]\npenalty = 2.0e5\n",
        "g.toml");
    const std::vector<GridPoint> points = expand_grid(g);
    REQUIRE(points.size() == 2 * 3 * 1 * 2);
    REQUIRE(points[0].other_axes.at("penalty_scale") == 0.0);
    REQUIRE(points[1].other_axes.at("penalty_scale") == 0.1);
    const Scene thesis = point_scene(g, points[0], ImpactModel::rigid);
    CHECK(thesis.contacts.at(0).penalty_mode == PenaltyMode::per_point);
    CHECK(thesis.contacts.at(0).penalty == 2e5);
    const Scene element = point_scene(g, points[1], ImpactModel::rigid);
    CHECK(element.contacts.at(0).penalty_mode == PenaltyMode::element);
    CHECK(element.contacts.at(0).penalty_scale == 0.1);
  }
  SECTION("errors") {
    const std::string with_axis =
        small_grid_with("KE = [10.0, 100.0]", "KE = [10.0]\npenalty_scale = [0.0, 0.1]");
    // [contact] is line 25 of kSmallGrid + "\n[contact]\n", its first key line 26.
    CHECK_THAT(grid_error_of(with_axis + "\n[contact]\npenalty_mode = \"element\"\n"),
               Catch::Contains("g.toml:26: contact.penalty_mode: the penalty_scale axis chooses "
                               "the mode at every point"));
    CHECK_THAT(
        grid_error_of(fmt::format("{}{}", kSmallGrid, "\n[contact]\npenalty_mode = \"elment\"\n")),
        Catch::Contains("g.toml:25: contact.penalty_mode: must be one of \"per_point\", "
                        "\"element\" (got \"elment\"; did you mean \"element\"?)"));
    CHECK_THAT(grid_error_of(fmt::format("{}{}", kSmallGrid, "\n[contact]\npenalty_scale = 0.1\n")),
               Catch::Contains("g.toml:25: contact.penalty_scale: applies only with "
                               "penalty_mode = \"element\""));
    CHECK_THAT(grid_error_of(fmt::format(
                   "{}{}", kSmallGrid, "\n[contact]\npenalty_mode = \"element\"\npenalty = 1e6\n")),
               Catch::Contains("g.toml:26: contact.penalty: applies only with penalty_mode = "
                               "\"per_point\""));
    CHECK_THAT(
        grid_error_of(fmt::format("{}{}", kSmallGrid,
                                  "\n[contact]\npenalty_mode = \"element\"\npenalty_scale = -1\n")),
        Catch::Contains("g.toml:26: contact.penalty_scale: must be > 0 (got -1)"));
    CHECK_THAT(
        grid_error_of(small_grid_with("KE = [10.0, 100.0]", "KE = [10.0]\npenalty_scale = [-0.1]")),
        Catch::Contains("g.toml:5: axes.penalty_scale: [0] must be >= 0 (got -0.1)"));
    CHECK_THAT(grid_error_of(small_grid_with("KE = [10.0, 100.0]",
                                             "KE = [10.0]\npenalty = [1e5, 1e6]\n"
                                             "penalty_scale = [0.0, 0.1]")),
               Catch::Contains("g.toml:1: axes: a penalty (K_P) axis and a penalty_scale axis "
                               "cannot be combined"));
    CHECK_THAT(
        grid_error_of(small_grid_with("KE = [10.0, 100.0]", "KE = [10.0]\npenalty = [1e5, 1e6]") +
                      "\n[contact]\npenalty_mode = \"element\"\n"),
        Catch::Contains("contact.penalty_mode: a penalty (K_P) axis needs the per-point "
                        "mode"));
    CHECK_THAT(grid_error_of(fmt::format("{}{}", kSmallGrid, "\n[contact]\ndampnig = 1.0\n")),
               Catch::Contains("g.toml:25: contact.dampnig: unknown key 'dampnig' (did you mean "
                               "'damping'?)"));
  }
}

TEST_CASE("a model's scene text leaves out the other model's axes (run reuse by scene text)",
          "[grid][element_penalty]") {
  // The ccm scene must not change with the rigid model's penalty, penalty_scale or damping, nor
  // the rigid scene with the ccm model's restitution or friction: the same run either way.
  const GridSpec g = parse_grid(kSmallGrid, "g.toml");
  const GridPoint base = point(1e2, 1.0, 50.0);
  const auto text = [&](std::map<std::string, double> axes, ImpactModel m) {
    GridPoint q = base;
    q.other_axes = std::move(axes);
    return point_scene_text(g, q, m);
  };
  const std::string ccm_text = text({{"damping", 0.0}, {"penalty_scale", 0.0}}, ImpactModel::ccm);
  CHECK(text({{"damping", 1.0}, {"penalty_scale", 0.1}}, ImpactModel::ccm) == ccm_text);
  CHECK(text({{"penalty", 3e5}}, ImpactModel::ccm) == point_scene_text(g, base, ImpactModel::ccm));
  CHECK(text({{"restitution", 0.5}}, ImpactModel::ccm) != ccm_text);  // its own axis does count
  const std::string rigid_text =
      text({{"restitution", 1.0}, {"friction", 0.0}}, ImpactModel::rigid);
  CHECK(text({{"restitution", 0.5}, {"friction", 0.3}}, ImpactModel::rigid) == rigid_text);
  CHECK(text({{"damping", 1.0}}, ImpactModel::rigid) !=
        point_scene_text(g, base, ImpactModel::rigid));
}

TEST_CASE("default-rigid-options.toml: the default grid with damping and penalty_scale axes",
          "[grid][element_penalty]") {
  const GridSpec base = parse_grid_file(CCM_SOURCE_DIR "/scenes/grids/default.toml");
  const GridSpec g = parse_grid_file(CCM_SOURCE_DIR "/scenes/grids/default-rigid-options.toml");
  CHECK(g.other_axes.at("damping") == std::vector<double>{0.0, 1.0});
  CHECK(g.other_axes.at("penalty_scale") == std::vector<double>{0.0, 0.1, 1.0});
  const std::vector<GridPoint> points = expand_grid(g);
  REQUIRE(points.size() == 36 * 6);
  // Point 4: ER 1, RLS 0.5, KE 10, damping 1, penalty_scale 0.1 (the last axis fastest).
  CHECK(points[4].other_axes ==
        std::map<std::string, double>{{"damping", 1.0}, {"penalty_scale", 0.1}});
  const Scene rigid = point_scene(g, points[4], ImpactModel::rigid);
  CHECK(rigid.contacts.at(0).penalty_mode == PenaltyMode::element);
  CHECK(rigid.contacts.at(0).damping == 1.0);
  // The ccm scene of every one of the six is the default grid's, word for word; the rigid one at
  // penalty_scale 0 and damping 1 is the default grid's but for the title.
  const GridPoint first = expand_grid(base)[0];
  for (size_t i = 0; i < 6; ++i)
    CHECK(point_scene_text(g, points[i], ImpactModel::ccm) ==
          point_scene_text(base, first, ImpactModel::ccm));
  const auto untitled = [](std::string text) {
    const size_t a = text.find("title = "), b = text.find('\n', a);
    return text.erase(a, b - a);
  };
  CHECK(untitled(point_scene_text(g, points[3], ImpactModel::rigid)) ==
        untitled(point_scene_text(base, first, ImpactModel::rigid)));
}

TEST_CASE(
    "the rigid model's meshed impactor: the ccm model's sphere made rigid, on the per-point "
    "penalty, its scene the same at every ER",
    "[grid][rigid-body]") {
  const GridSpec g = parse_grid(
      fmt::format("{}{}", kSmallGrid, "\n[contact]\nrigid_impactor = \"meshed\"\n"), "g.toml");
  CHECK(g.contact.meshed_rigid_impactor);
  const std::string text = point_scene_text(g, point(1e2, 1.0, 50.0), ImpactModel::rigid);
  CHECK_THAT(text, Catch::Contains("kind = \"rigid\"") && Catch::Contains("rigid = \"impactor\""));
  CHECK(text.find("[contact.sphere]") == std::string::npos);
  // The rigid run does not depend on ER: one scene, one run, for every ER.
  CHECK(point_scene_text(g, point(1e6, 1.0, 50.0), ImpactModel::rigid) == text);
  const Scene rigid = point_scene(g, point(1e2, 1.0, 50.0), ImpactModel::rigid);
  const BodySpec& impactor = body_named(rigid, kImpactorName);
  CHECK(impactor.rigid);
  // The same sphere as the ccm model's: mass m_I, speed v_I.
  const Scene ccm = point_scene(g, point(1e2, 1.0, 50.0), ImpactModel::ccm);
  CHECK(impactor.mass == body_named(ccm, kImpactorName).mass);
  CHECK(impactor.initial_velocity == body_named(ccm, kImpactorName).initial_velocity);
  CHECK_THAT(
      grid_error_of(fmt::format("{}{}", kSmallGrid, "\n[contact]\nrigid_impactor = \"meshd\"\n")),
      Catch::Contains("did you mean \"meshed\""));
  CHECK_THAT(grid_error_of(fmt::format(
                 "{}{}", kSmallGrid,
                 "\n[contact]\npenalty_mode = \"element\"\nrigid_impactor = \"meshed\"\n")),
             Catch::Contains("per-point K_P"));
  // It stands for a sphere: smoothed all over unless the grid says otherwise.
  CHECK(rigid.contacts.at(0).crease_angle == kMeshedImpactorCreaseAngle);
  const GridSpec flat =
      parse_grid(fmt::format("{}{}", kSmallGrid,
                             "\n[contact]\nrigid_impactor = \"meshed\"\ncrease_angle = 0\n"),
                 "g.toml");
  CHECK(point_scene(flat, point(1e2, 1.0, 50.0), ImpactModel::rigid).contacts.at(0).crease_angle ==
        0.0);
  CHECK_THAT(grid_error_of(fmt::format("{}{}", kSmallGrid, "\n[contact]\ncrease_angle = 45\n")),
             Catch::Contains("crease_angle") && Catch::Contains("meshed rigid impactor"));
  CHECK_THAT(
      grid_error_of(fmt::format("{}{}", kSmallGrid,
                                "\n[contact]\nrigid_impactor = \"meshed\"\ncrease_angle = 180\n")),
      Catch::Contains("crease_angle"));
}
