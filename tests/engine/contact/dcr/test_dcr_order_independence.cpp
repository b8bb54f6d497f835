// Evidence (contact): the DCR result does not depend on the numbering of the mesh. The same
// two-body impact is run twice, the second time with every node of both bodies renumbered by a
// random permutation and the tets listed in a random order; the final kinetic energy of each
// body must agree within 0.5 % (the figure).
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>

#include "engine/contact/dcr/dcr_contact.hpp"
#include "tests/support/contact_scenes.hpp"
#include "tests/support/models.hpp"
#include "tests/support/tolerance.hpp"

using namespace ccm;

namespace {

struct ImpactResult {
  double ke_ball = 0.0, ke_block = 0.0;
  int max_active = 0;
  RunSummary summary;
};

// A soft sphere fired obliquely at a free soft block (no supports): a contact patch with many
// simultaneous node-face and edge-edge constraints, shared nodes, sliding.
ImpactResult run_impact(bool renumber) {
  const double R = 0.01, gap = 2e-4;
  const MaterialParams mat = test::neo_hookean(1e6, 0.3, 1000.0);
  TetMesh block =
      test::translated(structured_box(Vec3(0.04, 0.04, 0.02), 8, 8, 4), Vec3(-0.02, -0.02, -0.02));
  TetMesh ball = test::gmsh_sphere(R, 0.004, Vec3(-0.003, 0.0017, R + gap));
  if (renumber) {
    block = test::permuted(block, 12345u);
    ball = test::permuted(ball, 67890u);
  }
  ModelMesh mesh;
  add_body(mesh, "block", mat, block);
  add_body(mesh, "ball", mat, ball);
  Model model = make_model(std::move(mesh));
  test::set_body_velocity(model, 1, Vec3(0.8, 0.0, -2.0));

  dcr::DcrSettings settings;
  settings.surfaces = {"block/boundary", "ball/boundary"};
  dcr::DcrContact contact(model.mesh, settings, model.bcs.fixed_nodes);
  RunOptions opt;
  opt.contact = &contact;
  opt.time.end_time = 6e-3;
  opt.time.output_interval = 1e-4;
  ImpactResult out;
  opt.on_sample = [&](const State& s) {
    out.max_active = std::max(out.max_active, contact.active_contacts());
    out.ke_block = test::kinetic_energy(s, model.mesh.bodies[0]);
    out.ke_ball = test::kinetic_energy(s, model.mesh.bodies[1]);
  };
  out.summary = run_explicit(model, opt);
  return out;
}

}  // namespace

TEST_CASE("DCR: a random renumbering of nodes and tets does not change an impact",
          "[dcr][order_independence]") {
  const auto start = std::chrono::steady_clock::now();
  const ImpactResult a = run_impact(false);
  const ImpactResult b = run_impact(true);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  INFO("verdicts " << to_string(a.summary.verdict) << " / " << to_string(b.summary.verdict) << " "
                   << a.summary.instability.reason << b.summary.instability.reason);
  INFO("KE ball " << a.ke_ball << " / " << b.ke_ball << " J (rel "
                  << test::relative_error(b.ke_ball, a.ke_ball) << "), KE block " << a.ke_block
                  << " / " << b.ke_block << " J (rel "
                  << test::relative_error(b.ke_block, a.ke_block) << ")");
  INFO("max active " << a.max_active << " / " << b.max_active << ", steps " << a.summary.steps
                     << " / " << b.summary.steps << ", wall (both) " << wall << " s");
  REQUIRE(a.summary.verdict == Verdict::completed);
  REQUIRE(b.summary.verdict == Verdict::completed);
  REQUIRE(a.max_active > 0);
  REQUIRE(b.max_active > 0);
  // The figure: each body's final kinetic energy within 0.5 %.
  CHECK(test::relative_error(b.ke_ball, a.ke_ball) < 0.005);
  CHECK(test::relative_error(b.ke_block, a.ke_block) < 0.005);
}
