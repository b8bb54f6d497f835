// Scene files: the examples parse and build; bad input gives a message naming the file, the
// line and the key; `ccm run` exits 2 on bad input without creating its output folder, and 0
// (or 3 when unstable) with its results written.
#include <fmt/format.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <numeric>
#include <sstream>
#include <string>

#include "engine/contact/rigid_sphere_penalty.hpp"
#include "engine/core/time_table.hpp"
#include "engine/solver/lumped_mass.hpp"
#include "run/scene/scene_builder.hpp"
#include "run/scene/scene_file.hpp"
#include "tests/support/scene_fixtures.hpp"

namespace fs = std::filesystem;
using Catch::Contains;
using namespace ccm;

namespace {

// A fresh folder, removed again at the end of the test.
struct TempDir {
  fs::path path;
  TempDir() {
    static int counter = 0;
    path = fs::temp_directory_path() / fmt::format("ccm-test-scene-{}-{}", getpid(), ++counter);
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(path / name, std::ios::binary) << text;
    return path / name;
  }
};

// A valid scene; the line numbers below are relied upon by the tests.
const std::string& kBase = test::kOneCubeScene;

// kBase with `from` (which must occur) replaced by `to`.
std::string with(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

std::string parse_error(const fs::path& file) {
  try {
    parse_scene_file(file);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string build_error(const fs::path& file) {
  const Scene scene = parse_scene_file(file);
  try {
    const Model model = build_model(scene);
    build_output_request(scene, model.mesh);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string read_file(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs `ccm run scene --out out`; returns the exit code, stderr into `err`.
int run_ccm(const TempDir& tmp, const fs::path& scene, const fs::path& out, std::string& err) {
  const fs::path err_file = tmp.path / "stderr.txt";
  const std::string cmd = fmt::format("'{}' run '{}' --out '{}' --quiet > /dev/null 2> '{}'",
                                      CCM_BINARY, scene.string(), out.string(), err_file.string());
  const int status = std::system(cmd.c_str());
  err = read_file(err_file);
  REQUIRE(WIFEXITED(status));
  return WEXITSTATUS(status);
}

const fs::path kExamples = fs::path(CCM_SOURCE_DIR) / "scenes" / "examples";

}  // namespace

TEST_CASE("the example scenes parse and build", "[scene]") {
  for (const char* name : {"default.toml", "bar_pulse.toml", "pipe_gravity.toml"}) {
    INFO(name);
    const Scene scene = parse_scene_file(kExamples / name);
    REQUIRE(scene.bodies.size() == 1);
    CHECK(scene.time.end > 0.0);
    CHECK(scene.warnings.empty());
    CHECK(!scene.output.track.empty());
    const Model model = build_model(scene);
    CHECK(model.mesh.n_elements() > 100);
    const OutputRequest out = build_output_request(scene, model.mesh);
    CHECK(out.tracked.size() == scene.output.track.size());
  }
  const Scene plate = parse_scene_file(kExamples / "default.toml");
  CHECK(plate.bodies[0].material.nu == 0.45);
  CHECK(plate.surface_loads.at(0).force.size() == 3);
  const Scene bar = parse_scene_file(kExamples / "bar_pulse.toml");
  CHECK(bar.bodies[0].material.model == MaterialModel::linear_elastic);
  CHECK(bar.bodies[0].material.nu == 0.0);
  const Scene pipe = parse_scene_file(kExamples / "pipe_gravity.toml");
  CHECK(pipe.gravity.z() == -9.81);
  CHECK(pipe.bodies[0].geometry.shape == Shape::pipe);
}

TEST_CASE("defaults of a minimal scene", "[scene]") {
  TempDir tmp;
  const Scene s = parse_scene_file(tmp.write("s.toml", kBase));
  CHECK(s.time.output_interval == Approx(1e-5));
  CHECK(s.time.dt_safety == 0.9);
  CHECK(!s.time.max_dt);
  CHECK(s.bodies[0].material.model == MaterialModel::neo_hookean);
  CHECK(s.bodies[0].geometry.primitive.kind == PrimitiveKind::box);
  CHECK(s.output.kinetic_energy);
  CHECK(s.gravity == Vec3::Zero());
}

TEST_CASE("scene errors name the file, the line and the key", "[scene]") {
  TempDir tmp;
  const auto error_of = [&](const std::string& text) {
    const fs::path f = tmp.write("s.toml", text);
    return parse_error(f);
  };
  const std::string f = (tmp.path / "s.toml").string();

  SECTION("unknown key") {
    CHECK(error_of(with(kBase, "rho = 1000.0", "densty = 1000.0")) ==
          f + ":8: bodies[0].material.densty: unknown key 'densty' (allowed: model, E, nu, rho)");
    CHECK_THAT(error_of(with(kBase, "end = 1e-3", "end = 1e-3\nmax_td = 1e-6")),
               Contains(f + ":3: time.max_td: unknown key 'max_td' (did you mean 'max_dt'?)"));
    CHECK_THAT(error_of("contcat = 1\n" + kBase), Contains(f + ":1: contcat: unknown key"));
  }
  SECTION("negative E") {
    CHECK(error_of(with(kBase, "E = 1e5", "E = -5")) ==
          f + ":6: bodies[0].material.E: must be > 0 (got -5)");
  }
  SECTION("nu >= 0.5") {
    CHECK(error_of(with(kBase, "nu = 0.3", "nu = 0.5")) ==
          f + ":7: bodies[0].material.nu: must lie in (-1, 0.5) (got 0.5)");
  }
  SECTION("zero density") {
    CHECK(error_of(with(kBase, "rho = 1000.0", "rho = 0")) ==
          f + ":8: bodies[0].material.rho: must be > 0 (got 0)");
  }
  SECTION("missing key: the line of the enclosing table") {
    CHECK(error_of(with(kBase, "nu = 0.3\n", "")) ==
          f + ":5: bodies[0].material.nu: required key is missing");
    CHECK(error_of(with(kBase, "[time]\nend = 1e-3\n", "")) ==
          f + ":1: time: required table is missing");
  }
  SECTION("wrong type") {
    CHECK(error_of(with(kBase, "E = 1e5", "E = \"soft\"")) ==
          f + ":6: bodies[0].material.E: expected a number, got a string");
    CHECK(error_of(with(kBase, "size = [0.01, 0.01, 0.01]", "size = [0.01, 0.01]")) ==
          f + ":11: bodies[0].geometry.size: expected an array of 3 numbers, got an array");
  }
  SECTION("shape-specific keys") {
    CHECK(error_of(with(kBase, "mesh_size", "inner_radius = 0.001\nmesh_size")) ==
          f + ":12: bodies[0].geometry.inner_radius: key 'inner_radius' does not apply to "
              "shape 'box'");
    CHECK(error_of(with(kBase, "shape = \"box\"", "shape = \"cube\"")) ==
          f + ":10: bodies[0].geometry.shape: must be one of sphere, box, cylinder, pipe, mesh "
              "(got 'cube')");
  }
  SECTION("time and names") {
    CHECK(error_of(with(kBase, "end = 1e-3", "end = 1e-3\ndt_safety = 2.5")) ==
          f + ":3: time.dt_safety: must lie in (0, 2] (got 2.5)");
    CHECK(error_of(kBase + "[[bodies]]\nname = \"cube\"\n") ==
          f + ":14: bodies[1].name: duplicate name 'cube' (also used by bodies[0])");
    CHECK_THAT(error_of(with(kBase, "name = \"cube\"", "name = \"a b\"")),
               Contains(":4: bodies[0].name: 'a b' is not a valid name"));
  }
  SECTION("selections and force tables") {
    CHECK(error_of(kBase + "[[fixed]]\nbody = \"cube\"\n") ==
          f + ":13: fixed[0]: needs one of: node_set, box, plane");
    CHECK(error_of(kBase +
                   "[[surface_loads]]\nplane = { point = [0, 0, 0], normal = [0, 0, 0] }\n") ==
          f + ":14: surface_loads[0].plane.normal: must be a non-zero vector");
    CHECK(error_of(kBase + "[[surface_loads]]\nsurface = \"cube/boundary\"\ndirection = [1, 0, 0]\n"
                           "force = [[0.0, 1.0], [0.0, 2.0]]\n") ==
          f + ":16: surface_loads[0].force: " + TimeTable::validate({{0.0, 1.0}, {0.0, 2.0}}));
  }
  SECTION("TOML syntax error") {
    CHECK_THAT(error_of(with(kBase, "nu = 0.3", "nu = ")), Contains(f + ":7: TOML syntax error:"));
  }
  SECTION("missing scene file") {
    CHECK(parse_error(tmp.path / "nope.toml") ==
          (tmp.path / "nope.toml").string() + ": no such file");
  }
}

TEST_CASE("dt_safety above 1 is allowed with a warning", "[scene]") {
  TempDir tmp;
  const fs::path f = tmp.write("s.toml", with(kBase, "end = 1e-3", "end = 1e-3\ndt_safety = 1.5"));
  const Scene s = parse_scene_file(f);
  REQUIRE(s.warnings.size() == 1);
  CHECK_THAT(s.warnings[0], Contains(f.string() + ":3: time.dt_safety: 1.5 > 1"));
}

TEST_CASE("mesh files: relative paths, placement, named surfaces and errors", "[scene]") {
  TempDir tmp;
  const std::string mesh_geometry =
      with(kBase, "shape = \"box\"\nsize = [0.01, 0.01, 0.01]\nmesh_size = 0.005\n",
           "shape = \"mesh\"\nfile = \"part.msh\"\n");
  const std::string f = (tmp.path / "s.toml").string();

  SECTION("missing mesh file") {
    const fs::path scene = tmp.write("s.toml", mesh_geometry);
    CHECK(parse_scene_file(scene).bodies[0].geometry.file == tmp.path / "part.msh");
    CHECK(build_error(scene) == f +
                                    ":11: bodies[0].geometry.file: body 'cube' cannot read its "
                                    "mesh file: " +
                                    (tmp.path / "part.msh").string() + ": no such file");
  }
  SECTION("garbage mesh file") {
    tmp.write("part.msh", "this is not a mesh\n");
    CHECK_THAT(
        build_error(tmp.write("s.toml", mesh_geometry)),
        Contains(f + ":11: bodies[0].geometry.file: body 'cube' cannot read its mesh file: " +
                 (tmp.path / "part.msh").string() + ": not a Gmsh MSH file"));
  }
  SECTION("garbage after a valid header") {
    tmp.write("part.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\nrubbish\n");
    CHECK_THAT(
        build_error(tmp.write("s.toml", mesh_geometry)),
        Contains(f + ":11: bodies[0].geometry.file: body 'cube' cannot read its mesh file: " +
                 (tmp.path / "part.msh").string()));
  }
  SECTION("a one-tet mesh file with a named surface, placed") {
    tmp.write("part.msh", R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
1
2 1 "bottom"
$EndPhysicalNames
$Nodes
4
1 0 0 0
2 1 0 0
3 0 1 0
4 0 0 1
$EndNodes
$Elements
2
1 2 2 1 1 1 3 2
2 4 2 2 2 1 2 3 4
$EndElements
)");
    const fs::path scene =
        tmp.write("s.toml", mesh_geometry +
                                "[bodies.placement]\ntranslate = [0, 0, 5]\n"
                                "[[fixed]]\nbody = \"cube\"\nnode_set = \"bottom\"\n");
    const Model model = build_model(parse_scene_file(scene));
    CHECK(model.mesh.n_elements() == 1);
    CHECK(model.mesh.X[0].z() == 5.0);
    CHECK(model.bcs.fixed_nodes == std::vector<int>{0, 1, 2});
  }
}

TEST_CASE("builder errors name the file, the line and the key", "[scene]") {
  TempDir tmp;
  const std::string f = (tmp.path / "s.toml").string();
  const auto error_of = [&](const std::string& extra) {
    return build_error(tmp.write("s.toml", kBase + extra));
  };
  CHECK(error_of("[[fixed]]\nbody = \"cub\"\nbox = { min = [0, 0, 0], max = [1, 1, 1] }\n") ==
        f + ":14: fixed[0].body: no body named 'cub' (bodies: cube)");
  CHECK(error_of("[[fixed]]\nplane = { point = [1, 0, 0], normal = [1, 0, 0] }\n") ==
        f + ":14: fixed[0].plane: selects no node");
  CHECK(error_of("[[fixed]]\nnode_set = \"cube/clamp\"\n") ==
        f + ":14: fixed[0].node_set: no node set named 'cube/clamp' (node sets: cube, "
            "cube/boundary)");
  CHECK(error_of("[[surface_loads]]\nplane = { point = [0, 0, 0.5], normal = [0, 0, 1] }\n"
                 "direction = [0, 0, 1]\nforce = [[0, 1]]\n") ==
        f + ":14: surface_loads[0].plane: selects no boundary triangle");
  CHECK(error_of("[[output.track]]\nname = \"p\"\nbody = \"ball\"\npoint = [0, 0, 0]\n") ==
        f + ":15: output.track[0].body: no body named 'ball' (bodies: cube)");
  // a mesh_size giving far too many tets: the mesher's message, at the geometry table
  CHECK_THAT(
      build_error(tmp.write("s.toml", with(kBase, "mesh_size = 0.005", "mesh_size = 1e-6"))),
      Contains(f + ":9: bodies[0].geometry: body 'cube' cannot be meshed: mesh_primitive(box)"));
}

TEST_CASE("ccm run: bad input exits 2 and creates nothing", "[scene][cli]") {
  REQUIRE(fs::exists(CCM_BINARY));
  TempDir tmp;
  const fs::path out = tmp.path / "out";
  std::string err;
  const fs::path bad = tmp.write("bad.toml", with(kBase, "E = 1e5", "E = -5"));
  CHECK(run_ccm(tmp, bad, out, err) == 2);
  CHECK(err == "ccm: error: " + bad.string() + ":6: bodies[0].material.E: must be > 0 (got -5)\n");
  CHECK(!fs::exists(out));

  const fs::path no_mesh = tmp.write(
      "no_mesh.toml", with(kBase, "shape = \"box\"\nsize = [0.01, 0.01, 0.01]\nmesh_size = 0.005\n",
                           "shape = \"mesh\"\nfile = \"gone.msh\"\n"));
  CHECK(run_ccm(tmp, no_mesh, out, err) == 2);
  CHECK_THAT(err, Contains("ccm: error: " + no_mesh.string() + ":11: bodies[0].geometry.file"));
  CHECK(!fs::exists(out));
}

TEST_CASE("ccm run: a tiny scene completes and writes its results", "[scene][cli]") {
  REQUIRE(fs::exists(CCM_BINARY));
  TempDir tmp;
  const fs::path out = tmp.path / "out" / "nested";
  const std::string text = kBase +
                           "[[output.track]]\nname = \"corner\"\nbody = \"cube\"\n"
                           "point = [0.01, 0.01, 0.01]\n";
  const fs::path scene =
      tmp.write("tiny.toml",
                with(text, "[bodies.material]", "initial_velocity = [0, 0, 1]\n[bodies.material]"));
  std::string err;
  CHECK(run_ccm(tmp, scene, out, err) == 0);
  CHECK(err.empty());
  REQUIRE(fs::exists(out / "history.csv"));
  CHECK_THAT(read_file(out / "history.csv"), Contains("time,cube.kinetic_energy"));
  CHECK_THAT(read_file(out / "history.csv"), Contains("corner.vz"));
  CHECK(read_file(out / "scene.toml") == read_file(scene));
  const std::string summary = read_file(out / "summary.toml");
  CHECK_THAT(summary, Contains("verdict = \"completed\""));
  CHECK_THAT(summary, Contains("scene_fnv1a64 = \""));
  CHECK(!fs::exists(out / "history.csv.partial"));
}

TEST_CASE("ccm run: a run that ends unstable exits 3 with its results", "[scene][cli]") {
  REQUIRE(fs::exists(CCM_BINARY));
  TempDir tmp;
  const fs::path out = tmp.path / "out";
  const fs::path scene = tmp.write("s.toml", with(kBase, "end = 1e-3", "end = 1.0\nmax_steps = 3"));
  std::string err;
  CHECK(run_ccm(tmp, scene, out, err) == 3);
  CHECK(fs::exists(out / "history.csv"));
  const std::string summary = read_file(out / "summary.toml");
  CHECK_THAT(summary, Contains("verdict = \"unstable\""));
  CHECK_THAT(summary, Contains("reason = \"step limit reached before the end time\""));
}

TEST_CASE("body mass and a refined mesh zone", "[scene]") {
  TempDir tmp;
  const std::string sphere =
      "[time]\nend = 1e-3\n[[bodies]]\nname = \"ball\"\nmass = 2.0\n[bodies.material]\nE = 1e5\n"
      "nu = 0.3\nrho = 1000.0\n[bodies.geometry]\nshape = \"sphere\"\nradius = 0.01\n"
      "mesh_size = 0.004\nrefine = { center = [0.0, 0.0, -0.01], radius = 0.004, mesh_size = 0.001 "
      "}\n";
  const auto total_mass = [](const Model& m) {
    const std::vector<double> lumped = lumped_mass(m.mesh, m.elements);
    return std::accumulate(lumped.begin(), lumped.end(), 0.0);
  };
  SECTION("mass: the density is mass / meshed volume") {
    const Scene s = parse_scene_file(tmp.write("s.toml", sphere));
    REQUIRE(s.bodies[0].mass);
    REQUIRE(s.bodies[0].geometry.primitive.refinement);
    CHECK(s.bodies[0].geometry.primitive.refinement->mesh_size == 0.001);
    const Model with_mass = build_model(s);
    CHECK(total_mass(with_mass) == Approx(2.0).epsilon(1e-12));
    // Without it: rho times the inscribed polyhedron's volume, below rho 4/3 pi r^3 = 4.19 g.
    const Model nominal =
        build_model(parse_scene_file(tmp.write("n.toml", with(sphere, "mass = 2.0\n", ""))));
    CHECK(total_mass(nominal) < 1000.0 * 4.0 / 3.0 * std::numbers::pi * 1e-6);
    CHECK(total_mass(nominal) > 0.95 * 1000.0 * 4.0 / 3.0 * std::numbers::pi * 1e-6);
    // The refined zone: more tets than the same sphere without it.
    const Model plain = build_model(parse_scene_file(
        tmp.write("p.toml", with(sphere,
                                 "refine = { center = [0.0, 0.0, -0.01], radius = 0.004, "
                                 "mesh_size = 0.001 }\n",
                                 ""))));
    CHECK(with_mass.mesh.n_elements() > 2 * plain.mesh.n_elements());
  }
  SECTION("errors") {
    const std::string f = (tmp.path / "s.toml").string();
    CHECK(parse_error(tmp.write("s.toml", with(sphere, "mass = 2.0", "mass = -1.0"))) ==
          f + ":5: bodies[0].mass: must be > 0 (got -1)");
    CHECK(parse_error(
              tmp.write("s.toml", with(sphere, "mesh_size = 0.001 }", "mesh_size = 0.01 }"))) ==
          f + ":14: bodies[0].geometry.refine.mesh_size: must not exceed the body's mesh_size "
              "(0.01 > 0.004)");
    CHECK(parse_error(
              tmp.write("s.toml", with(sphere, "radius = 0.004,", "radius = 0.004, r = 1,"))) ==
          f + ":14: bodies[0].geometry.refine.r: unknown key 'r' (allowed: center, radius, "
              "mesh_size, transition)");
    CHECK(parse_error(tmp.write("s.toml", with(sphere, "mesh_size = 0.001 }",
                                               "mesh_size = 0.001, transition = 0 }"))) ==
          f + ":14: bodies[0].geometry.refine.transition: must be > 0 (got 0)");
  }
}

TEST_CASE("[contact] rigid_penalty: penalty_mode and penalty_scale", "[scene][element_penalty]") {
  // Line 13 [contact], 14 model, 15 body, 16 the first key below.
  const std::string head = kBase + "[contact]\nmodel = \"rigid_penalty\"\nbody = \"cube\"\n";
  const std::string sphere =
      "[contact.sphere]\nradius = 0.01\nmass = 0.1\ncenter = [0.005, 0.005, 0.02]\n";
  SECTION("defaults: the thesis's K_P per point; the element mode's s is 0.1") {
    const Scene s = parse_scene(head + sphere, "s.toml");
    CHECK(s.contacts.at(0).penalty_mode == PenaltyMode::per_point);
    CHECK(s.contacts.at(0).penalty == 1e6);
    const Scene e = parse_scene(head + "penalty_mode = \"element\"\n" + sphere, "s.toml");
    CHECK(e.contacts.at(0).penalty_mode == PenaltyMode::element);
    CHECK(e.contacts.at(0).penalty_scale == 0.1);
  }
  SECTION("the element mode builds, with k = s K A^2 / V per triangle in its description") {
    const Scene s =
        parse_scene(head + "penalty_mode = \"element\"\npenalty_scale = 0.5\n" + sphere, "s.toml");
    CHECK(s.contacts.at(0).penalty_scale == 0.5);
    const Model model = build_model(s);
    const ContactSetup setup = build_contact(s, model);
    const auto& rp = dynamic_cast<const RigidSpherePenalty&>(*setup.model);
    CHECK(rp.params().penalty_mode == PenaltyMode::element);
    CHECK(rp.params().penalty_scale == 0.5);
    CHECK(rp.point_stiffness(0) > 0.0);
    CHECK_THAT(setup.description, Contains("element penalty s 0.5 (k = s K A^2 / V"));
    // The per-point description is the one it always was.
    const Scene p = parse_scene(head + "penalty = 2e5\n" + sphere, "s.toml");
    CHECK_THAT(build_contact(p, build_model(p)).description, Contains("K_P 2e+05 N/m per point"));
  }
  SECTION("errors: an unknown mode, a key of the other mode, a scale <= 0") {
    CHECK(test::scene_error_of(head + "penalty_mode = \"elemnt\"\n" + sphere) ==
          "s.toml:16: contact.penalty_mode: must be one of \"per_point\", \"element\" (got "
          "\"elemnt\"; did you mean \"element\"?)");
    CHECK(test::scene_error_of(head + "penalty_mode = \"area\"\n" + sphere) ==
          "s.toml:16: contact.penalty_mode: must be one of \"per_point\", \"element\" (got "
          "\"area\")");
    CHECK(test::scene_error_of(head + "penalty_scale = 0.1\n" + sphere) ==
          "s.toml:16: contact.penalty_scale: applies only with penalty_mode = \"element\"");
    CHECK_THAT(test::scene_error_of(head + "penalty_mode = \"element\"\npenalty = 1e6\n" + sphere),
               Contains("s.toml:17: contact.penalty: applies only with penalty_mode = "
                        "\"per_point\""));
    CHECK(test::scene_error_of(head + "penalty_mode = \"element\"\npenalty_scale = 0\n" + sphere) ==
          "s.toml:17: contact.penalty_scale: must be > 0 (got 0)");
    CHECK(test::scene_error_of(head + "penalty_scael = 0.1\n" + sphere) ==
          "s.toml:16: contact.penalty_scael: unknown key 'penalty_scael' (did you mean "
          "'penalty_scale'?)");
  }
}
