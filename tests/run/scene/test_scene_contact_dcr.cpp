// Scene [contact] model = "dcr": parsing, defaults, errors with file, line and key, the builder
// and the example; the contact failure verdict (ContactModel::failure) of the integrator.
#include <catch2/catch.hpp>
#include <limits>
#include <string>
#include <vector>

#include "engine/contact/dcr/dcr_contact.hpp"
#include "engine/contact/rigid_sphere_penalty.hpp"
#include "run/scene/scene_builder.hpp"
#include "run/scene/scene_file.hpp"
#include "tests/support/scene_fixtures.hpp"

using Catch::Contains;
using namespace ccm;

namespace {

// Two cubes, 1 mm apart along z; lines 1-24. [contact] goes on line 25.
const std::string kTwoCubes = test::kTimeToml + test::cube_body_toml("a") +
                              test::cube_body_toml("b") +
                              "[bodies.placement]\ntranslate = [0.0, 0.0, 0.011]\n";
using test::scene_error_of;

std::string build_error_of(const std::string& text) {
  const Scene scene = parse_scene(text, "s.toml");
  const Model model = build_model(scene);
  try {
    build_contact(scene, model);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "(no error)";
}

// A contact model that reports a failure from a given step on.
class FailingContact : public ContactModel {
 public:
  explicit FailingContact(int fail_at)
      : ContactModel("failing", kCorrectionPhases), fail_at_(fail_at) {}
  void begin_step(const State& /*state*/, double /*dt*/) override {}
  void add_forces(State& /*state*/) override {}
  void correct(State& /*state*/, double /*dt*/) override {}
  void end_step(const State& /*state*/, double /*dt*/) override {
    ++steps_;
    if (steps_ >= fail_at_) ledger_.failure = "gave up";
  }
  ContactStepBound step_bound(const State& /*state*/, double /*ceiling*/) const override {
    return {};
  }
  double corrected_elements_stable_dt() const override {
    return std::numeric_limits<double>::infinity();
  }
  int steps() const { return steps_; }

 private:
  int fail_at_;
  int steps_ = 0;
};

}  // namespace

TEST_CASE("scene [contact]: dcr parses and builds", "[contact][scene][dcr]") {
  const Scene scene = parse_scene(kTwoCubes + R"([contact]
model = "dcr"
surfaces = ["a", "b/boundary"]
self_contact = true
restitution = 0.5
friction = 0.3
)",
                                  "s.toml");
  const ContactSpec& c = scene.contacts.at(0);
  REQUIRE(c.kind == ContactKind::dcr);
  CHECK(c.surfaces == std::vector<std::string>{"a", "b/boundary"});
  CHECK(c.self_contact);
  CHECK(c.restitution == 0.5);
  CHECK(c.friction == 0.3);

  const Model model = build_model(scene);
  const ContactSetup setup = build_contact(scene, model);
  REQUIRE(setup.model);
  REQUIRE(setup.histories.size() == 1);
  CHECK(setup.model_name == "dcr");
  CHECK_THAT(setup.description, Contains("a/boundary, b/boundary") && Contains("restitution 0.5"));
  CHECK(!setup.histories[0]->history_columns().empty());
  CHECK(setup.model->ledger().failure.empty());

  // Defaults: no self contact, e = 0, mu = 0.
  const Scene d =
      parse_scene(kTwoCubes + "[contact]\nmodel = \"dcr\"\nsurfaces = [\"a\", \"b\"]\n", "s.toml");
  CHECK(!d.contacts.at(0).self_contact);
  CHECK(d.contacts.at(0).restitution == 0.0);
  CHECK(d.contacts.at(0).friction == 0.0);
}

TEST_CASE("scene [contact]: dcr errors name the file, the line and the key",
          "[contact][scene][dcr]") {
  const std::string head = kTwoCubes + "[contact]\nmodel = \"dcr\"\n";  // lines 25, 26
  CHECK(scene_error_of(head + "surfaces = [\"a\"]\nrestitution = 1.5\n") ==
        "s.toml:28: contact.restitution: must lie in [0, 1] (got 1.5)");
  CHECK(scene_error_of(head + "surfaces = [\"a\"]\nfriction = -0.1\n") ==
        "s.toml:28: contact.friction: must be >= 0 (got -0.1)");
  CHECK(scene_error_of(head + "surfaces = [\"a\"]\nbody = \"a\"\n") ==
        "s.toml:28: contact.body: unknown key 'body' (allowed: model, surfaces, self_contact, "
        "restitution, friction, force_axis, sensors)");
  CHECK(scene_error_of(head) == "s.toml:25: contact.surfaces: required key is missing");
  CHECK(scene_error_of(head + "surfaces = \"a\"\n") ==
        "s.toml:27: contact.surfaces: expected an array of strings, got a string");
  CHECK(scene_error_of(head + "surfaces = []\n") ==
        "s.toml:27: contact.surfaces: needs at least one surface");
  CHECK(scene_error_of(head + "surfaces = [\"a\", 3]\n") ==
        "s.toml:27: contact.surfaces[1]: expected a string, got an integer");
  CHECK(scene_error_of(head + "surfaces = [\"a\"]\nself_contact = 1\n") ==
        "s.toml:28: contact.self_contact: expected a boolean (true or false), got an "
        "integer");
  CHECK(build_error_of(head + "surfaces = [\"a\", \"c\"]\n") ==
        "s.toml:27: contact.surfaces: no surface named 'c/boundary' (surfaces: a/boundary, "
        "b/boundary)");
  CHECK(build_error_of(head + "surfaces = [\"a\", \"a/boundary\"]\n") ==
        "s.toml:27: contact.surfaces: surface 'a/boundary' is listed twice");
  CHECK(scene_error_of(head + "surfaces = [\"a\"]\nforce_axis = [0.0, 0.0, 0.0]\n") ==
        "s.toml:28: contact.force_axis: must be a non-zero vector");
  CHECK(build_error_of(head + "surfaces = [\"a\"]\nsensors = [\"a/pad\"]\n") ==
        "s.toml:28: contact.sensors: no surface named 'a/pad' (surfaces: a/boundary, b/boundary)");
}

TEST_CASE("scene [contact]: dcr force and pressure output, when asked", "[contact][scene][dcr]") {
  const Scene scene = parse_scene(kTwoCubes + R"([contact]
model = "dcr"
surfaces = ["a", "b"]
force_axis = [0.0, 0.0, -1.0]
sensors = ["b/boundary"]
)",
                                  "s.toml");
  REQUIRE(scene.contacts.at(0).force_axis);
  CHECK(scene.contacts.at(0).sensors == std::vector<std::string>{"b/boundary"});
  const Model model = build_model(scene);
  const ContactSetup setup = build_contact(scene, model);
  const std::vector<std::string> cols = setup.histories[0]->history_columns();
  for (const char* c :
       {"contact.a.b.force", "contact.a.b.force_axis", "contact.b/boundary.pressure"})
    CHECK(std::find(cols.begin(), cols.end(), c) != cols.end());
}

TEST_CASE("scene [contact]: the ball_on_plate_dcr example parses and builds",
          "[contact][scene][dcr]") {
  const Scene scene =
      parse_scene_file(std::string(CCM_SOURCE_DIR) + "/scenes/examples/ball_on_plate_dcr.toml");
  CHECK(scene.warnings.empty());
  REQUIRE(scene.contacts.at(0).kind == ContactKind::dcr);
  const Model model = build_model(scene);
  const ContactSetup setup = build_contact(scene, model);
  REQUIRE(setup.model);
  const auto& dcr = dynamic_cast<const dcr::DcrContact&>(*setup.model);
  CHECK(dcr.min_edge() > 0.0);
  CHECK(dcr.failure().empty());
}

TEST_CASE("a contact failure ends the run unstable with its reason and time", "[contact]") {
  const Scene scene = parse_scene(kTwoCubes, "s.toml");
  const Model model = build_model(scene);
  FailingContact contact(7);
  RunOptions opt;
  opt.time.end_time = 1.0;
  opt.contact = &contact;
  const RunSummary r = run_explicit(model, opt);
  CHECK(r.verdict == Verdict::unstable);
  CHECK(r.steps == 7);
  CHECK(contact.steps() == 7);
  CHECK(r.instability.reason == "contact (failing): gave up");
  CHECK(r.instability.time == Approx(r.end_time));
  CHECK(r.instability.time > 0.0);
}

TEST_CASE("rigid_penalty: a sphere sinking past half its radius ends the run", "[contact]") {
  // K_P = 1 N/m cannot stop a 1 kg sphere at 1 m/s: it sinks into the cube.
  const Scene scene = parse_scene(kTwoCubes + R"([contact]
model = "rigid_penalty"
body = "a"
penalty = 1.0
sphere = { radius = 0.004, mass = 1.0, center = [0.005, 0.005, 0.0145], velocity = [0, 0, -1] }
)",
                                  "s.toml");
  const Model model = build_model(scene);
  const ContactSetup setup = build_contact(scene, model);
  RunOptions opt;
  opt.time.end_time = 0.02;
  opt.contact = setup.model.get();
  const RunSummary r = run_explicit(model, opt);
  REQUIRE(r.verdict == Verdict::unstable);
  CHECK_THAT(r.instability.reason, Contains("contact (rigid_penalty): penetration") &&
                                       Contains("exceeds 0.5 x the sphere radius (0.004 m)"));
  // The sphere reaches half its radius of depth (2 mm) after about 2.5 ms.
  CHECK(r.instability.time > 2e-3);
  CHECK(r.instability.time < 4e-3);
}
