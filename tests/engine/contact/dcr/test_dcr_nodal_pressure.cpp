// DCR contact between bodies of the averaged-nodal-pressure tet (docs/elements.md): two nearly
// incompressible rubber blocks (nu = 0.499) collide obliquely. What must hold whatever the
// element: total momentum is conserved (equal and opposite impulses: 1e-10 relative, round-off of
// the sums over 2 x 10^3 steps), the energy balance closes (1 % as for the plain tet's contact
// tests; the projection update books the nodal volumetric energy exactly, and without it this run
// was 100 % off), no node ends inside a foreign tet (the independent checker, tolerance as in
// test_dcr_no_penetration.cpp), and the blocks do separate again.
#include <catch2/catch.hpp>
#include <cmath>

#include "engine/contact/dcr/dcr_contact.hpp"
#include "tests/support/models.hpp"
#include "tests/support/penetration_checker.hpp"
#include "tests/support/tolerance.hpp"
#include "tests/support/two_bodies.hpp"

using namespace ccm;

namespace {

Model rubber_blocks(ElementKind element) {
  const MaterialParams rubber{MaterialModel::neo_hookean, 1e6, 0.499, 1000.0};
  const double side = 0.02, gap = 2e-4;
  ModelMesh mesh;
  add_body(mesh, "a", rubber, structured_box(Vec3(side, side, side), 4, 4, 4));
  add_body(mesh, "b", rubber,
           test::translated(structured_box(Vec3(side, side, side), 4, 4, 4),
                            Vec3(side + gap, 0.3 * side, 0.2 * side)));
  for (Body& b : mesh.bodies) b.element = element;
  Model model = make_model(std::move(mesh));
  const Body& a = model.mesh.bodies[0];
  for (int n = a.first_node; n < a.first_node + a.n_nodes; ++n)
    model.initial_velocity[static_cast<size_t>(n)] = Vec3(2.0, 0.0, 0.0);
  return model;
}

}  // namespace

TEST_CASE("DCR with nodal-pressure bodies: momentum, energy, no penetration",
          "[dcr][nodal_pressure]") {
  const Model model = rubber_blocks(ElementKind::nodal_pressure);
  dcr::DcrSettings settings;
  settings.surfaces = {"a/boundary", "b/boundary"};
  settings.restitution = 1.0;
  dcr::DcrContact contact(model.mesh, settings, model.bcs.fixed_nodes);

  RunOptions opt;
  opt.contact = &contact;
  opt.time.end_time = 6e-3;  // 0.1 ms to contact, ~2 ms in contact at 2 m/s, then apart
  opt.time.output_interval = 5e-5;
  Vec3 p0 = Vec3::Zero();
  bool first = true, touched = false;
  State last;
  double p_error = 0.0;
  size_t worst_inside = 0;
  opt.on_sample = [&](const State& s) {
    const Vec3 p = test::linear_momentum(s);
    if (first) p0 = p;
    first = false;
    p_error = std::max(p_error, (p - p0).norm() / p0.norm());
    touched = touched || contact.active_contacts() > 0;
    worst_inside =
        std::max(worst_inside, test::nodes_inside_foreign_tets(model.mesh, s.x, 1e-6).size());
    last = s;
  };
  const RunSummary summary = run_explicit(model, opt);

  INFO("verdict " << to_string(summary.verdict) << " " << summary.instability.reason);
  REQUIRE(summary.verdict == Verdict::completed);
  CHECK(touched);
  CHECK(p_error < 1e-10);
  CHECK(summary.energy_balance_error < 0.01);
  CHECK(worst_inside == 0);
  const Vec3 v_a = test::mean_velocity(last, model.mesh.bodies[0]);
  const Vec3 v_b = test::mean_velocity(last, model.mesh.bodies[1]);
  INFO("v_a " << v_a.transpose() << ", v_b " << v_b.transpose());
  CHECK(v_b.x() > v_a.x());  // apart again: b moves away from a
}
