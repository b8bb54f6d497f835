// [[contact.pairs]] (docs/scene-file.md, "Contact pairs"): one contact model per pair, in one
// run. A free rigid slab between two soft cubes, DCR above it and penalty below, keeps the total
// linear momentum of the three bodies (both contacts exchange momentum exactly: the DCR's
// impulses and the penalty's reaction both act on the slab); the pairs' history columns carry
// their names; what a pair may not do is refused with file, line and key.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>

#include "engine/contact/contact_set.hpp"
#include "run/scene/scene_builder.hpp"
#include "run/scene/scene_file.hpp"
#include "tests/support/scene_fixtures.hpp"

using Catch::Contains;
using namespace ccm;

namespace {

// Lines: the three bodies, then the pairs.
std::string three_bodies() {
  std::string s = "[time]\nend = 4e-3\noutput_interval = 1e-4\n";
  s += "[[bodies]]\nname = \"top\"\ninitial_velocity = [0.0, 0.0, -1.0]\n[bodies.material]\n"
       "E = 1e5\nnu = 0.3\nrho = 1000.0\n[bodies.geometry]\nshape = \"box\"\n"
       "size = [0.01, 0.01, 0.01]\nmesh_size = 0.005\n[bodies.placement]\n"
       "translate = [0.0, 0.0, 0.0052]\n";
  s += "[[bodies]]\nname = \"slab\"\nkind = \"rigid\"\n[bodies.material]\nE = 1e9\nnu = 0.3\n"
       "rho = 1000.0\n[bodies.geometry]\nshape = \"box\"\nsize = [0.02, 0.02, 0.005]\n"
       "mesh_size = 0.005\n[bodies.placement]\ntranslate = [-0.005, -0.005, 0.0]\n";
  s += "[[bodies]]\nname = \"bottom\"\ninitial_velocity = [0.0, 0.0, 0.5]\n[bodies.material]\n"
       "E = 1e5\nnu = 0.3\nrho = 1000.0\n[bodies.geometry]\nshape = \"box\"\n"
       "size = [0.01, 0.01, 0.01]\nmesh_size = 0.005\n[bodies.placement]\n"
       "translate = [0.0, 0.0, -0.0101]\n";
  return s;
}

const std::string kUpper =
    "[[contact.pairs]]\nname = \"upper\"\nmodel = \"dcr\"\nsurfaces = [\"top\", \"slab\"]\n";
const std::string kLower =
    "[[contact.pairs]]\nname = \"lower\"\nmodel = \"penalty\"\nbody = \"bottom\"\n"
    "rigid = \"slab\"\npenalty = 1e4\n";

}  // namespace

TEST_CASE("contact pairs: DCR above and penalty below a free rigid slab keep the total momentum",
          "[contact][scene][rigid-body]") {
  const Scene scene = parse_scene(three_bodies() + kUpper + kLower, "s.toml");
  REQUIRE(scene.contacts.size() == 2);
  CHECK(scene.contacts[0].name == "upper");
  CHECK(scene.contacts[1].kind == ContactKind::rigid_penalty);
  const Model model = build_model(scene);
  ContactSetup setup = build_contact(scene, model);
  REQUIRE(dynamic_cast<ContactSet*>(setup.model.get()));
  CHECK(setup.model_name == "dcr + rigid_penalty");
  CHECK(setup.model->phases().adds_forces);
  CHECK(setup.model->phases().corrects);
  REQUIRE(setup.histories.size() == 2);
  CHECK(setup.histories[0]->history_columns().front() == "upper.active");
  CHECK(setup.histories[1]->history_columns().front() == "lower.active_points");

  RunOptions opt;
  opt.time = time_control(scene.time);
  opt.contact = setup.model.get();
  // The total linear momentum of the deformable nodes and the slab, at every sample.
  Vec3 p0 = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  double worst = 0.0, scale = 0.0;
  Vec3 slab_velocity = Vec3::Zero();
  opt.on_sample = [&](const State& s) {
    Vec3 p = Vec3::Zero();
    for (size_t i = 0; i < s.v.size(); ++i) p += s.m_lumped[i] * s.v[i];
    for (const RigidState& r : s.rigid) p += r.velocity / r.inverse_mass;
    if (std::isnan(p0.x())) {
      p0 = p;
      scale = 0.0;
      for (size_t i = 0; i < s.v.size(); ++i) scale += s.m_lumped[i] * s.v[i].norm();
    }
    worst = std::max(worst, (p - p0).norm());
    slab_velocity = s.rigid.at(0).velocity;
  };
  const RunSummary run = run_explicit(model, opt);
  INFO(run.instability.reason);
  REQUIRE(run.verdict == Verdict::completed);
  // Both contacts acted: the top cube (1 m/s down, 0.2 mm above) and the bottom one (0.5 m/s
  // up, 0.1 mm below) reach the slab at 0.2 ms; each pair did work, and the slab moves.
  const auto& members = dynamic_cast<ContactSet&>(*setup.model).members();
  CHECK(members[0]->ledger().work < 0.0);  // the DCR's inelastic contact dissipates
  CHECK(members[1]->ledger().work != 0.0);
  CHECK(std::abs(slab_velocity.z()) > 0.01);
  // Exchanged momentum is kept to round-off: 1e-12 of the bodies' total |m v| (each step's sums
  // round at 1e-16 relative; 4,000 steps at most).
  CHECK(worst <= 1e-12 * scale);
}

TEST_CASE("contact pairs: what a pair may not be is refused with file, line and key",
          "[contact][scene]") {
  const std::string bodies = three_bodies();
  // Two DCR pairs sharing the slab: one solve must hold both (one pair, three surfaces).
  const std::string second_dcr =
      "[[contact.pairs]]\nname = \"under\"\nmodel = \"dcr\"\nsurfaces = [\"bottom\", \"slab\"]\n";
  CHECK_THAT(test::assembly_error_of(bodies + kUpper + second_dcr),
             Contains("s.toml:") && Contains("contact.pairs") && Contains("surfaces") &&
                 Contains("also in DCR pair 'upper'") && Contains("list all of their surfaces"));
  // A name used twice, a name that is a body's, an unknown model, "none" as a pair, a stray key.
  CHECK_THAT(test::assembly_error_of(bodies + kUpper + kUpper),
             Contains("pair name 'upper' is used twice"));
  CHECK_THAT(test::assembly_error_of(bodies + "[[contact.pairs]]\nname = \"top\"\nmodel = \"dcr\"\n"
                                              "surfaces = [\"top\", \"slab\"]\n"),
             Contains("'top' is also the name of a body"));
  CHECK_THAT(test::assembly_error_of(bodies + "[[contact.pairs]]\nmodel = \"none\"\n"),
             Contains("contact.pairs") && Contains("must be one of \"dcr\""));
  CHECK_THAT(test::assembly_error_of(bodies + kUpper + "restitution = 0.5\nsensor = [\"top\"]\n"),
             Contains("unknown key 'sensor'") && Contains("did you mean 'sensors'"));
  // [contact] with pairs takes nothing else.
  CHECK_THAT(test::assembly_error_of(bodies + "[contact]\nmodel = \"dcr\"\n" + kUpper),
             Contains("contact.model") && Contains("unknown key"));
  // Unnamed pairs are pair1, pair2, ... in their history columns.
  const Scene unnamed = parse_scene(bodies +
                                        "[[contact.pairs]]\nmodel = \"dcr\"\nsurfaces = "
                                        "[\"top\", \"slab\"]\n" +
                                        kLower,
                                    "s.toml");
  CHECK(unnamed.contacts.at(0).name == "pair1");
  CHECK(test::assembly_error_of(bodies + kUpper + kLower) == "(no error)");
}

TEST_CASE("contact pairs: the pad, limb and table example runs with both of its pairs acting",
          "[contact][scene][heavy]") {
  const Scene scene =
      parse_scene_file(std::string(CCM_SOURCE_DIR) + "/scenes/examples/pad_limb_table_pairs.toml");
  const Model model = build_model(scene);
  ContactSetup setup = build_contact(scene, model);
  REQUIRE(setup.histories.size() == 2);
  RunOptions opt;
  opt.time = time_control(scene.time);
  opt.time.end_time = 0.012;  // the pad lands at 0.5 ms, the limb on the table at about 8 ms
  opt.monitor = scene.monitor;
  opt.contact = setup.model.get();
  int pad_contacts = 0, table_points = 0;
  std::vector<double> row;
  opt.on_sample = [&](const State& s) {
    row.clear();
    setup.histories[0]->append_history(s, row);
    pad_contacts = std::max(pad_contacts, static_cast<int>(row[0]));  // pad_limb.active
    row.clear();
    setup.histories[1]->append_history(s, row);
    table_points = std::max(table_points, static_cast<int>(row[0]));  // on_table.active_points
  };
  const RunSummary run = run_explicit(model, opt);
  INFO(run.instability.reason);
  REQUIRE(run.verdict == Verdict::completed);
  CHECK(pad_contacts > 0);
  CHECK(table_points > 0);
  // The balance closes with both pairs' work in it (the monitor's tolerance is 5 %).
  CHECK(run.energy_balance_error < 0.01);
}
