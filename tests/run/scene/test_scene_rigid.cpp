// Scene bodies with kind = "rigid" (docs/scene-file.md, docs/rigid-bodies.md): parsing, the
// builder (mass properties, held nodes), and every refusal naming the file, the line and the key;
// the project's pad-on-limb example run with its pad deformable and rigid.
#include <catch2/catch.hpp>
#include <fstream>
#include <string>

#include "run/scene/scene_builder.hpp"
#include "run/scene/scene_file.hpp"
#include "run/scene/scene_run.hpp"
#include "tests/support/scene_fixtures.hpp"

using Catch::Contains;
using namespace ccm;

namespace {

// One cube with its rigid keys from line 5 on, before its material table.
std::string rigid_cube(const std::string& keys) {
  std::string body = test::cube_body_toml("cube");
  const auto at = body.find("[bodies.material]");
  return test::kTimeToml + body.substr(0, at) + keys + body.substr(at);
}

}  // namespace

TEST_CASE(
    "scene: a rigid body parses, builds with the mass of its meshed volume, and leaves its "
    "elements out of the step",
    "[rigid-body][scene]") {
  const Scene scene =
      parse_scene(rigid_cube("kind = \"rigid\"\ninitial_velocity = [0.0, 0.0, -1.0]\n"
                             "initial_angular_velocity = [0.0, 0.0, 2.0]\n"),
                  "s.toml");
  REQUIRE(scene.bodies.size() == 1);
  CHECK(scene.bodies[0].rigid);
  CHECK(scene.bodies[0].motion == RigidMotion::free);
  const Model model = build_model(scene);
  REQUIRE(model.rigid_bodies.size() == 1);
  const RigidBodyModel& r = model.rigid_bodies[0];
  // 1 cm cube of 1000 kg/m^3: 1 g, I = m a^2 / 6 (round-off: the tets integrate exactly).
  CHECK(r.mass.mass == Approx(1e-3).epsilon(1e-12));
  CHECK(r.mass.inertia(2, 2) == Approx(1e-3 * 1e-4 / 6.0).epsilon(1e-12));
  CHECK(r.velocity == Vec3(0.0, 0.0, -1.0));
  CHECK(r.angular_velocity == Vec3(0.0, 0.0, 2.0));
  CHECK(model.mesh.bodies[0].rigid);
  CHECK(model.elements.schedule.slabs.empty());
}

TEST_CASE("scene: a prescribed rigid body reads its velocity histories", "[rigid-body][scene]") {
  const Scene scene =
      parse_scene(rigid_cube("kind = \"rigid\"\nmotion = \"prescribed\"\n"
                             "velocity = [[0.0, 0.0, 0.0, 0.0], [1e-3, 0.0, 0.0, -2.0]]\n"),
                  "s.toml");
  const Model model = build_model(scene);
  const RigidBodyModel& r = model.rigid_bodies.at(0);
  CHECK(r.motion == RigidMotion::prescribed);
  CHECK(r.prescribed_velocity[2](5e-4) == Approx(-1.0));
  CHECK(r.prescribed_angular_velocity[0](5e-4) == 0.0);
}

TEST_CASE("scene: rigid keys in the wrong place are refused with file, line and key",
          "[rigid-body][scene]") {
  using test::scene_error_of;
  CHECK_THAT(scene_error_of(rigid_cube("kind = \"rigd\"\n")),
             Contains("s.toml:5") && Contains("kind") && Contains("did you mean \"rigid\""));
  CHECK_THAT(scene_error_of(rigid_cube("motion = \"free\"\n")),
             Contains("s.toml:5") && Contains("applies only to kind = \"rigid\""));
  CHECK_THAT(scene_error_of(rigid_cube("kind = \"rigid\"\nmotion = \"pinned\"\n")),
             Contains("s.toml:6") && Contains("motion"));
  CHECK_THAT(scene_error_of(rigid_cube("kind = \"rigid\"\nvelocity = [[0.0, 0.0, 0.0, 1.0]]\n")),
             Contains("s.toml:6") && Contains("applies only to motion = \"prescribed\""));
  CHECK_THAT(scene_error_of(rigid_cube("kind = \"rigid\"\nmotion = \"prescribed\"\n")),
             Contains("s.toml:6") && Contains("prescribed needs velocity"));
  CHECK_THAT(
      scene_error_of(rigid_cube("kind = \"rigid\"\nmotion = \"fixed\"\ninitial_velocity = [0.0, "
                                "0.0, 1.0]\n")),
      Contains("s.toml:7") && Contains("applies only to motion = \"free\""));
  CHECK_THAT(
      scene_error_of(rigid_cube("kind = \"rigid\"\nmotion = \"prescribed\"\n"
                                "velocity = [[1.0, 0.0, 0.0, 1.0], [0.5, 0.0, 0.0, 1.0]]\n")),
      Contains("s.toml:7") && Contains("velocity"));
  CHECK_THAT(scene_error_of(rigid_cube("kind = \"rigid\"\nmotion = \"prescribed\"\n"
                                       "velocity = [[0.0, 1.0, 1.0]]\n")),
             Contains("velocity[0]") && Contains("[t, x, y, z]"));
}

TEST_CASE(
    "scene: fixed nodes and loads on a rigid body, and the sphere's penalty on one, are "
    "refused by the builder",
    "[rigid-body][scene]") {
  const std::string fixed_rigid =
      rigid_cube("kind = \"rigid\"\n") + "[[fixed]]\nbody = \"cube\"\nnode_set = \"boundary\"\n";
  CHECK_THAT(test::assembly_error_of(fixed_rigid), Contains("s.toml:16") &&
                                                       Contains("rigid body 'cube'") &&
                                                       Contains("motion = \"fixed\""));
  const std::string loaded_fixed =
      rigid_cube("kind = \"rigid\"\nmotion = \"fixed\"\n") +
      "[[surface_loads]]\nbody = \"cube\"\nsurface = \"boundary\"\ndirection = [0.0, 0.0, 1.0]\n"
      "force = [[0.0, 1.0]]\n";
  CHECK_THAT(test::assembly_error_of(loaded_fixed),
             Contains("s.toml:17") && Contains("whose motion is \"fixed\""));
  const std::string penalty = rigid_cube("kind = \"rigid\"\n") +
                              "[contact]\nmodel = \"rigid_penalty\"\nbody = \"cube\"\n"
                              "[contact.sphere]\nradius = 0.005\nmass = 0.01\n"
                              "center = [0.005, 0.005, 0.02]\n";
  CHECK_THAT(test::assembly_error_of(penalty), Contains("body 'cube' is rigid"));
}

TEST_CASE(
    "scene: rigid_penalty against a meshed rigid body builds, runs, and refuses what does "
    "not apply",
    "[rigid-body][scene][penalty]") {
  // A soft cube resting 0.1 mm above a rigid slab, falling under gravity.
  const std::string slab =
      "[[bodies]]\nname = \"slab\"\nkind = \"rigid\"\nmotion = \"fixed\"\n[bodies.material]\n"
      "E = 1e9\nnu = 0.3\nrho = 1000.0\n[bodies.geometry]\nshape = \"box\"\n"
      "size = [0.03, 0.03, 0.005]\nmesh_size = 0.005\n[bodies.placement]\n"
      "translate = [-0.01, -0.01, -0.0051]\n";
  const std::string base = test::kTimeToml + "[gravity]\nacceleration = [0.0, 0.0, -9.81]\n" +
                           test::cube_body_toml("cube") + slab;
  const std::string contact =
      "[contact]\nmodel = \"rigid_penalty\"\nbody = \"cube\"\nrigid = \"slab\"\npenalty = 1e4\n";
  const Scene scene = parse_scene(base + contact, "s.toml");
  REQUIRE(scene.contacts.at(0).rigid);
  const Model model = build_model(scene);
  ContactSetup setup = build_contact(scene, model);
  REQUIRE(setup.model);
  RunOptions opt;
  opt.time.end_time = 0.01;
  opt.time.output_interval = 1e-3;
  opt.contact = setup.model.get();
  double lowest = 1.0;
  opt.on_sample = [&](const State& s) {
    const Body& cube = model.mesh.bodies[0];
    for (int n = cube.first_node; n < cube.first_node + cube.n_nodes; ++n)
      lowest = std::min(lowest, s.x[n].z());
  };
  const RunSummary run = run_explicit(model, opt);
  INFO(run.instability.reason);
  REQUIRE(run.verdict == Verdict::completed);
  // The cube fell 0.1 mm onto the slab and was held there: it sank into the slab by no more than
  // its weight over the springs of the points in contact could push it (about 1 mm at most).
  CHECK(lowest < 0.0);
  CHECK(lowest > -1e-3);

  CHECK_THAT(
      test::assembly_error_of(base + "[contact]\nmodel = \"rigid_penalty\"\nbody = \"cube\"\n"
                                     "rigid = \"cube\"\n"),
      Contains("body 'cube' is not rigid"));
  CHECK_THAT(test::assembly_error_of(base + contact + "penalty_mode = \"element\"\n"),
             Contains("penalty") && Contains("s.toml"));
  CHECK_THAT(test::assembly_error_of(base + contact +
                                     "[contact.sphere]\nradius = 0.01\nmass = 0.1\n"
                                     "center = [0.0, 0.0, 0.1]\n"),
             Contains("give only one of: sphere, rigid"));
  // The crease angle: read for a meshed rigid body, in [0, 180) degrees, refused elsewhere.
  CHECK(
      parse_scene(base + contact + "crease_angle = 30.0\n", "s.toml").contacts.at(0).crease_angle ==
      30.0);
  CHECK(parse_scene(base + contact, "s.toml").contacts.at(0).crease_angle == kDefaultCreaseAngle);
  CHECK_THAT(test::assembly_error_of(base + contact + "crease_angle = 180.0\n"),
             Contains("s.toml") && Contains("crease_angle") && Contains("[0, 180)"));
  CHECK_THAT(
      test::assembly_error_of(
          base + "[contact]\nmodel = \"rigid_penalty\"\nbody = \"cube\"\ncrease_angle = 30.0\n"
                 "[contact.sphere]\nradius = 0.01\nmass = 0.1\ncenter = [0.0, 0.0, 0.1]\n"),
      Contains("crease_angle") && Contains("applies only to a meshed rigid body"));
}

TEST_CASE("scene: a pinned rigid body reads its pin, turns about it, and refuses what does not fit",
          "[rigid-body][scene]") {
  // The cube (0..1 cm) on a pin along y through its edge at x = 0, z = 1 cm, under gravity.
  const std::string pin =
      "kind = \"rigid\"\nmotion = \"pinned\"\n[bodies.pin]\npoint = [0.0, 0.0, 0.01]\n"
      "axis = [0.0, 1.0, 0.0]\n";
  const std::string gravity = "[gravity]\nacceleration = [0.0, 0.0, -9.81]\n";
  const Scene scene = parse_scene(rigid_cube(pin) + gravity, "s.toml");
  CHECK(scene.bodies[0].motion == RigidMotion::pinned);
  const Model model = build_model(scene);
  REQUIRE(model.rigid_bodies.size() == 1);
  CHECK(model.rigid_bodies[0].pin.point == Vec3(0.0, 0.0, 0.01));
  CHECK(model.rigid_bodies[0].pin.mu_s == 0.0);
  RunOptions opt;
  opt.time.end_time = 0.02;
  opt.time.max_dt = 1e-4;
  const Vec3 p(0.0, 0.0, 0.01), c0(0.005, 0.005, 0.005);
  double worst = 0.0;
  Vec3 c = c0;
  opt.on_sample = [&](const State& s) {
    c = s.rigid.at(0).center;
    // The centre keeps its distance to the axis and its place along it (round-off).
    const Vec3 d = c - p, d0 = c0 - p;
    worst = std::max({worst, std::abs(d.y() - d0.y()),
                      std::abs(std::hypot(d.x(), d.z()) - std::hypot(d0.x(), d0.z()))});
  };
  const RunSummary run = run_explicit(model, opt);
  REQUIRE(run.verdict == Verdict::completed);
  CHECK(worst < 1e-15);
  CHECK(c.x() < c0.x());  // it swings down, its centre toward the point under the pin

  const std::string body = rigid_cube("kind = \"rigid\"\nmotion = \"pinned\"\n");
  CHECK_THAT(test::assembly_error_of(body),
             Contains("s.toml:6: bodies[0].motion") && Contains("[bodies.pin]"));
  CHECK_THAT(
      test::assembly_error_of(rigid_cube("kind = \"rigid\"\n[bodies.pin]\n"
                                         "point = [0.0, 0.0, 0.0]\naxis = [0.0, 1.0, 0.0]\n")),
      Contains("bodies[0].pin") && Contains("motion = \"pinned\""));
  CHECK_THAT(
      test::assembly_error_of(rigid_cube(
          "kind = \"rigid\"\nmotion = \"pinned\"\ninitial_angular_velocity = [1.0, 0.0, 0.0]\n"
          "[bodies.pin]\npoint = [0.0, 0.0, 0.0]\naxis = [0.0, 1.0, 0.0]\n")),
      Contains("initial_angular_velocity") && Contains("along the pin's axis"));
  CHECK_THAT(test::assembly_error_of(rigid_cube(pin + "mu_s = 0.2\n")),
             Contains("bodies[0].pin.mu_s") && Contains("both a coefficient and a radius"));
  CHECK_THAT(test::assembly_error_of(rigid_cube(pin + "mu_s = 0.2\nmu_k = 0.3\nradius = 0.001\n")),
             Contains("bodies[0].pin.mu_k") && Contains("at most mu_s"));
  CHECK_THAT(test::assembly_error_of(rigid_cube(
                 "kind = \"rigid\"\nmotion = \"pinned\"\n[bodies.pin]\npoint = [0.0, 0.0, 0.0]\n"
                 "axis = [0.0, 0.0, 0.0]\n")),
             Contains("bodies[0].pin.axis"));
  CHECK_THAT(test::assembly_error_of(rigid_cube(
                 "kind = \"rigid\"\nmotion = \"pinned\"\ninitial_velocity = [1.0, 0.0, 0.0]\n"
                 "[bodies.pin]\npoint = [0.0, 0.0, 0.0]\naxis = [0.0, 1.0, 0.0]\n")),
             Contains("initial_velocity") && Contains("motion = \"free\""));
}

TEST_CASE("scene: a rigid body's inertia and centre may be given, and must be a body's",
          "[rigid-body][scene]") {
  // A 1 cm cube of 1 g given the inertia of a long rod about its centre, spun about z at
  // 10 rad/s: its kinetic energy is Izz w^2 / 2 with the given Izz, not the cube's.
  const std::string given =
      "kind = \"rigid\"\ninertia = [2e-6, 2e-6, 3e-6, 0.0, 0.0, 0.0]\n"
      "center_of_mass = [0.005, 0.005, 0.004]\ninitial_angular_velocity = [0.0, 0.0, 10.0]\n";
  const Scene scene = parse_scene(rigid_cube(given), "s.toml");
  const Model model = build_model(scene);
  REQUIRE(model.rigid_bodies.size() == 1);
  const RigidBodyModel& r = model.rigid_bodies[0];
  CHECK(r.mass.inertia(2, 2) == 3e-6);
  CHECK(r.mass.center == Vec3(0.005, 0.005, 0.004));
  RunOptions opt;
  opt.time.end_time = 1e-3;
  opt.time.max_dt = 1e-5;
  double ke = 0.0;
  opt.on_sample = [&](const State& s) { ke = s.rigid.at(0).kinetic_energy; };
  REQUIRE(run_explicit(model, opt).verdict == Verdict::completed);
  CHECK(ke == Approx(0.5 * 3e-6 * 100.0).epsilon(1e-12));

  CHECK_THAT(test::assembly_error_of(rigid_cube("kind = \"rigid\"\ninertia = [1.0, 1.0, -1.0, 0.0, "
                                                "0.0, 0.0]\n")),
             Contains("s.toml:6: bodies[0].inertia") && Contains("positive definite"));
  CHECK_THAT(test::assembly_error_of(rigid_cube("kind = \"rigid\"\ninertia = [1.0, 1.0, 3.0, 0.0, "
                                                "0.0, 0.0]\n")),
             Contains("bodies[0].inertia") && Contains("triangle inequality"));
  CHECK_THAT(test::assembly_error_of(rigid_cube("inertia = [1.0, 1.0, 1.0, 0.0, 0.0, 0.0]\n")),
             Contains("bodies[0].inertia") && Contains("kind = \"rigid\""));
  CHECK_THAT(test::assembly_error_of(rigid_cube("kind = \"rigid\"\ninertia = [1.0, 1.0]\n")),
             Contains("bodies[0].inertia") && Contains("6 numbers"));
  CHECK_THAT(
      test::assembly_error_of(rigid_cube("kind = \"rigid\"\ncenter_of_mass = [0.0, 0.0, 0.0]\n")),
      Contains("bodies[0].center_of_mass") && Contains("given inertia"));
}

TEST_CASE(
    "scene: the flap-on-pin example completes: a ball struck off a pinned or free rigid plate at "
    "e = 0 is not mistaken for an injection",
    "[rigid-body][scene][dcr]") {
  // The ball separates from the flap it struck (the flap swings away faster); at the episode's end
  // the pair restitution (e = 0) pulls the two together: the impulse speeds the ball up and slows
  // the flap more. The check that DCR only dissipates must count the flap's share (it takes it as
  // a held impulse): counting the ball's alone read 15 % of the energy injected and ended the run.
  const std::string example = std::string(CCM_SOURCE_DIR) + "/scenes/examples/flap_on_pin.toml";
  for (const char* motion : {"pinned", "free"}) {
    Scene scene = parse_scene_file(example);
    if (std::string(motion) == "free") scene.bodies[0].motion = RigidMotion::free;
    const SceneRun run = assemble_scene_run(std::move(scene));
    RunOptions opt = scene_run_options(run, nullptr);
    opt.time.end_time = 0.01;
    const RunSummary s = run_explicit(run.model, opt);
    INFO(motion << ": " << s.instability.reason);
    REQUIRE(s.verdict == Verdict::completed);
    CHECK(run.contact.model->ledger().injected_energy < 1e-6);
    CHECK(s.energy_balance_error < 1e-3);
  }
}
