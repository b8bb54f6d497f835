// The sensor's contact force as the thesis measured it (3.3.3, eq. 3.8's F_c): the probe around
// the DCR sums m (v_after - v_before) of the sensor's nodes over the contact steps. Two bars
// end-on: all the momentum the struck bar gets comes through the contact, so the probe's impulse
// over its contact face equals that bar's final momentum, and the wrapped model's figures are
// passed through unchanged.
#include <catch2/catch.hpp>
#include <cmath>

#include "engine/contact/dcr/dcr_contact.hpp"
#include "rig_models/sim/contact_probe.hpp"
#include "tests/support/models.hpp"
#include "tests/support/tolerance.hpp"
#include "tests/support/two_bodies.hpp"

using namespace ccm;

TEST_CASE("contact probe: the impulse on the struck face is the struck bar's momentum",
          "[rig][probe]") {
  const double L = 0.05, w = 0.01, E = 1e6, rho = 1000.0, v0 = 0.1, gap = 1e-4;
  const MaterialParams mat{MaterialModel::neo_hookean, E, 0.0, rho};
  ModelMesh mesh;
  add_body(mesh, "a", mat, structured_box(Vec3(L, w, w), 5, 2, 2));
  add_body(mesh, "b", mat,
           test::translated(structured_box(Vec3(L, w, w), 5, 2, 2), Vec3(L + gap, 0.0, 0.0)));
  Model model = make_model(std::move(mesh));
  const Body& a = model.mesh.bodies[0];
  for (int n = a.first_node; n < a.first_node + a.n_nodes; ++n)
    model.initial_velocity[static_cast<size_t>(n)] = Vec3(v0, 0.0, 0.0);
  dcr::DcrSettings settings;
  settings.surfaces = {"a/boundary", "b/boundary"};
  settings.restitution = 1.0;
  dcr::DcrContact dcr(model.mesh, settings, model.bcs.fixed_nodes);
  // The sensor: b's whole surface. (Its face toward a alone misses the small impulses of the
  // contacts at its rim, which also move the side triangles' inner nodes: 4e-8 of the total.)
  rig::ContactProbe probe(dcr, model.mesh.node_sets.at("b/boundary"), Vec3::UnitX());
  CHECK(probe.name() == "dcr");
  RunOptions opt;
  opt.contact = &probe;
  opt.time.end_time = gap / v0 + 2 * L / std::sqrt(E / rho) + 5e-3;
  double v_b = 0.0;
  opt.on_sample = [&](const State& s) { v_b = test::mean_velocity(s, model.mesh.bodies[1]).x(); };
  const RunSummary r = run_explicit(model, opt);
  REQUIRE(r.verdict == Verdict::completed);
  const double mass_b = rho * L * w * w;  // the lumped masses sum to rho V exactly
  const double p_b = v_b;
  INFO("probe impulse " << probe.impulse() << " N s, b's momentum " << mass_b * p_b);
  CHECK(v_b > 0.9 * v0);  // the velocities were exchanged (e = 1)
  // Only contact acts on b, and only on its surface nodes: round-off.
  CHECK(test::relative_error(probe.impulse(), mass_b * p_b) < 1e-10);
  CHECK(probe.work() == dcr.work());
}
