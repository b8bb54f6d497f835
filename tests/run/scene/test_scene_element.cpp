// Scene [[bodies]] element = "tet4" | "nodal_pressure" (docs/scene-file.md, docs/elements.md):
// the default, the option reaching the model, and the refusals (an unknown name with a
// suggestion, a linear-elastic body) with file, line and key; DCR contact takes the element.
#include <algorithm>
#include <catch2/catch.hpp>
#include <string>

#include "engine/solver/explicit_integrator.hpp"
#include "run/scene/scene_builder.hpp"
#include "run/scene/scene_file.hpp"
#include "tests/support/scene_fixtures.hpp"

using Catch::Contains;
using namespace ccm;

namespace {

// The one-cube scene with `line` added after the body's name (line 5 of the scene).
std::string cube_with(const std::string& line) {
  std::string text = test::kOneCubeScene;
  const std::string name = "name = \"cube\"\n";
  const size_t at = text.find(name);
  REQUIRE(at != std::string::npos);
  return text.insert(at + name.size(), line + "\n");
}

}  // namespace

TEST_CASE("scene: a body's element defaults to tet4 and nodal_pressure reaches the model",
          "[nodal_pressure][scene]") {
  const Scene plain = parse_scene(test::kOneCubeScene, "s.toml");
  CHECK(plain.bodies[0].element == ElementKind::tet4);
  const Scene np = parse_scene(cube_with("element = \"nodal_pressure\""), "s.toml");
  CHECK(np.bodies[0].element == ElementKind::nodal_pressure);
  const Model model = build_model(np);
  CHECK(model.mesh.bodies[0].element == ElementKind::nodal_pressure);
  REQUIRE(model.elements.blocks.size() == 1);
  CHECK(model.elements.blocks[0].element == ElementKind::nodal_pressure);
  CHECK(model.elements.nodal.V0.size() == static_cast<size_t>(model.mesh.n_nodes()));
  const Scene explicit_plain = parse_scene(cube_with("element = \"tet4\""), "s.toml");
  CHECK(build_model(explicit_plain).elements.nodal.empty());
}

TEST_CASE("scene: a bad element is refused with file, line and key", "[nodal_pressure][scene]") {
  CHECK(test::scene_error_of(cube_with("element = \"nodal_presure\"")) ==
        "s.toml:5: bodies[0].element: must be one of \"tet4\", \"nodal_pressure\" (got "
        "\"nodal_presure\"; did you mean \"nodal_pressure\"?)");
  CHECK(test::scene_error_of(cube_with("element = \"hex8\"")) ==
        "s.toml:5: bodies[0].element: must be one of \"tet4\", \"nodal_pressure\" (got \"hex8\")");
  std::string linear = cube_with("element = \"nodal_pressure\"");
  linear.insert(linear.find("E = 1e5"), "model = \"linear_elastic\"\n");
  CHECK(test::scene_error_of(linear) ==
        "s.toml:5: bodies[0].element: nodal_pressure needs material model neo_hookean (got "
        "'linear_elastic')");
}

TEST_CASE("scene: dcr contact takes a nodal_pressure body", "[nodal_pressure][scene]") {
  const std::string text = cube_with("element = \"nodal_pressure\"") +
                           "[contact]\nmodel = \"dcr\"\nsurfaces = [\"cube\"]\n";
  const Scene scene = parse_scene(text, "s.toml");
  CHECK(scene.contacts.at(0).kind == ContactKind::dcr);
  CHECK(scene.bodies[0].element == ElementKind::nodal_pressure);
}

TEST_CASE("scene: the nearly incompressible example parses and builds with nodal_pressure",
          "[nodal_pressure][scene]") {
  const Scene scene = parse_scene_file(std::string(CCM_SOURCE_DIR) +
                                       "/scenes/examples/rubber_pad_nearly_incompressible.toml");
  REQUIRE(scene.bodies.size() == 1);
  CHECK(scene.bodies[0].element == ElementKind::nodal_pressure);
  CHECK(scene.bodies[0].material.nu == 0.499);
  CHECK(scene.warnings.empty());
  const Model model = build_model(scene);
  CHECK(model.elements.blocks[0].element == ElementKind::nodal_pressure);
  CHECK(model.mesh.n_elements() > 100);
}

namespace {

struct PadRun {
  RunSummary summary;
  double deepest = 0.0;  // the pad's largest mean downward displacement [m]
};

PadRun run_pad_on_limb(ElementKind tissue) {
  Scene scene =
      parse_scene_file(std::string(CCM_SOURCE_DIR) + "/scenes/examples/pad_on_limb_dcr.toml");
  scene.bodies[0].element = tissue;
  const Model model = build_model(scene);
  const ContactSetup setup = build_contact(scene, model);
  const Body& pad = model.mesh.bodies[1];
  PadRun out;
  RunOptions opt;
  opt.contact = setup.model.get();
  opt.time = time_control(scene.time);
  opt.on_sample = [&](const State& s) {
    double dz = 0.0;
    for (int n = pad.first_node; n < pad.first_node + pad.n_nodes; ++n)
      dz += s.x[static_cast<size_t>(n)].z() - model.mesh.X[static_cast<size_t>(n)].z();
    out.deepest = std::max(out.deepest, -dz / pad.n_nodes);
  };
  out.summary = run_explicit(model, opt);
  return out;
}

}  // namespace

// The example's claim: with DCR contact the nodal-pressure tissue (nu = 0.499) lets the pad sink
// in where the plain tet locks. Both complete with the energy booked (1 %, the contact tests'
// bound); the nodal-pressure indentation is at least 1.3 x the plain tet's (measured: 1.6 x at the
// pad's centre), a margin well above the mesh's effect on either.
TEST_CASE("scene: the pad-on-limb example runs, and its nodal-pressure tissue does not lock",
          "[nodal_pressure][scene][dcr]") {
  const PadRun np = run_pad_on_limb(ElementKind::nodal_pressure);
  const PadRun plain = run_pad_on_limb(ElementKind::tet4);
  INFO("nodal_pressure " << np.deepest << " m, tet4 " << plain.deepest << " m");
  REQUIRE(np.summary.verdict == Verdict::completed);
  REQUIRE(plain.summary.verdict == Verdict::completed);
  CHECK(np.summary.energy_balance_error < 0.01);
  CHECK(plain.summary.energy_balance_error < 0.01);
  CHECK(np.deepest > 1.3 * plain.deepest);
}
