// The contact impulse probe (io/fields/contact_impulse_probe.hpp) against momentum balance: on a
// free body with no load, the contact is the only external force, so the sum of the impulses it
// measured on the body's nodes must equal the change of the body's momentum — for a constraint
// model (DCR) and a penalty model (rigid sphere). Tolerance 1e-9 of the initial momentum: the
// round-off of thousands of steps (internal forces sum to zero per tet to round-off). And the
// probe must not change the run: the same positions, bit for bit.
#include <catch2/catch.hpp>

#include "engine/body/rigid_body_model.hpp"
#include "engine/contact/dcr/dcr_contact.hpp"
#include "engine/contact/rigid_sphere_penalty.hpp"
#include "io/fields/contact_impulse_probe.hpp"
#include "tests/support/contact_scenes.hpp"
#include "tests/support/models.hpp"
#include "tests/support/two_bodies.hpp"

using namespace ccm;
using namespace ccm::fields;

namespace probe_test {

Vec3 body_momentum(const State& s, const Body& b) {
  Vec3 p = Vec3::Zero();
  for (int n = b.first_node; n < b.first_node + b.n_nodes; ++n)
    p += s.m_lumped[static_cast<size_t>(n)] * s.v[static_cast<size_t>(n)];
  return p;
}

Vec3 probed_impulse(const ContactImpulseProbe& probe, const Body& b) {
  Vec3 sum = Vec3::Zero();
  for (size_t k = 0; k < probe.nodes().size(); ++k)
    if (probe.nodes()[k] >= b.first_node && probe.nodes()[k] < b.first_node + b.n_nodes)
      sum += probe.impulses()[k];
  return sum;
}

struct ProbeOutcome {
  std::vector<Vec3> x;
  std::vector<Vec3> p_first, p_last;  // per body
};

// Runs with `contact` (wrapped by `probe` when it is not null) and records every body's momentum.
ProbeOutcome run_probed(const Model& model, ContactModel& contact, ContactImpulseProbe* probe,
                        double end) {
  RunOptions opt;
  opt.contact = probe ? static_cast<ContactModel*>(probe) : &contact;
  opt.time.end_time = end;
  opt.time.output_interval = end / 10;
  ProbeOutcome out;
  opt.on_sample = [&](const State& s) {
    out.p_last.clear();
    for (const Body& b : model.mesh.bodies) out.p_last.push_back(body_momentum(s, b));
    if (out.p_first.empty()) out.p_first = out.p_last;
    out.x = s.x;
  };
  const RunSummary summary = run_explicit(model, opt);
  REQUIRE(summary.verdict == Verdict::completed);
  return out;
}

std::vector<int> all_boundary_nodes(const Model& m) {
  std::vector<Triangle> all;
  for (const Body& b : m.mesh.bodies) all.insert(all.end(), b.boundary.begin(), b.boundary.end());
  return nodes_of(all);
}

}  // namespace probe_test

using namespace probe_test;

TEST_CASE("Contact impulse probe: DCR impulses on each body equal its momentum change",
          "[fields]") {
  // Two soft bars end-on, one at 0.1 m/s, 0.1 mm apart: contact at 1 ms, over by 4 ms.
  const MaterialParams mat{MaterialModel::neo_hookean, 1e5, 0.0, 1000.0};
  ModelMesh mesh;
  add_body(mesh, "a", mat, structured_box(Vec3(0.02, 0.01, 0.01), 4, 2, 2));
  add_body(
      mesh, "b", mat,
      test::translated(structured_box(Vec3(0.02, 0.01, 0.01), 4, 2, 2), Vec3(0.0201, 0.0, 0.0)));
  Model model = make_model(std::move(mesh));
  const Body& a = model.mesh.bodies[0];
  for (int n = a.first_node; n < a.first_node + a.n_nodes; ++n)
    model.initial_velocity[static_cast<size_t>(n)] = Vec3(0.1, 0.0, 0.0);
  dcr::DcrSettings settings;
  settings.surfaces = {"a/boundary", "b/boundary"};
  const double end = 6e-3;

  dcr::DcrContact plain(model.mesh, settings, model.bcs.fixed_nodes);
  const ProbeOutcome without = run_probed(model, plain, nullptr, end);
  dcr::DcrContact inner(model.mesh, settings, model.bcs.fixed_nodes);
  ContactImpulseProbe probe(inner, all_boundary_nodes(model));
  const ProbeOutcome with = run_probed(model, inner, &probe, end);

  CHECK(with.x == without.x);  // the probe only watches
  const double p0 = with.p_first[0].norm();
  const Vec3 on_b = probed_impulse(probe, model.mesh.bodies[1]);
  CHECK(on_b.x() > 0.5 * p0);  // the bars did collide: most of the momentum went over
  for (size_t b = 0; b < 2; ++b) {
    const Vec3 dp = with.p_last[b] - with.p_first[b];
    CHECK((probed_impulse(probe, model.mesh.bodies[b]) - dp).norm() <= 1e-9 * p0);
  }
}

TEST_CASE("Contact impulse probe: rigid-sphere penalty forces, integrated as the engine does",
          "[fields]") {
  // A free soft box and a rigid sphere coming down on it from 0.5 mm: it bounces back.
  Model model =
      test::box_model(Vec3(0.02, 0.02, 0.01), 4, 4, 2, test::neo_hookean(1e5, 0.3, 1000.0));
  // A slow drift: a body exactly at rest has only round-off energy, which the monitor's
  // relative energy balance reads as noise (as in the rigid-sphere tests).
  for (Vec3& v : model.initial_velocity) v = Vec3(0.0, 1e-3, 0.0);
  RigidSpherePenaltyParams p;
  p.sphere.radius = 0.01;
  p.sphere.mass = 2e-3;
  p.sphere.center = Vec3(0.01, 0.01, 0.02 + 5e-4);
  p.sphere.velocity = Vec3(0.0, 0.0, -0.5);
  p.penalty = 2e3;
  const auto& surface = model.mesh.surfaces.at("box/boundary").triangles;
  const double end = 8e-3;

  RigidSpherePenalty plain(surface, p);
  const ProbeOutcome without = run_probed(model, plain, nullptr, end);
  RigidSpherePenalty inner(surface, p);
  ContactImpulseProbe probe(inner, all_boundary_nodes(model));
  const ProbeOutcome with = run_probed(model, inner, &probe, end);

  CHECK(with.x == without.x);
  const double p_sphere = p.sphere.mass * 0.5;
  const Vec3 on_box = probed_impulse(probe, model.mesh.bodies[0]);
  CHECK(on_box.z() < -0.5 * p_sphere);  // the sphere did hit the box
  CHECK((on_box - (with.p_last[0] - with.p_first[0])).norm() <= 1e-9 * p_sphere);
}

TEST_CASE("Contact impulse probe: a free rigid body still takes the DCR impulses through the probe",
          "[fields][rigid-body]") {
  // A soft ball (R 10 mm) at 1 m/s onto a free rigid block: the block is pushed only by the
  // impulses the contact gives its held nodes (ContactModel::add_held_impulses), which the probe
  // must pass on. With and without the probe, the same run bit for bit, and the block moves.
  ModelMesh mesh;
  add_body(
      mesh, "block", test::neo_hookean(1e8, 0.3, 1000.0),
      test::translated(structured_box(Vec3(0.04, 0.04, 0.01), 8, 8, 2), Vec3(-0.02, -0.02, -0.01)));
  add_body(mesh, "ball", test::neo_hookean(1e6, 0.3, 1000.0),
           test::gmsh_sphere(0.01, 0.003, Vec3(0.002, 0.001, 0.0102)));
  const RigidBodyModel block = make_rigid(mesh, 0, RigidMotion::free);
  Model model = make_model(std::move(mesh));
  model.rigid_bodies.push_back(block);
  test::set_body_velocity(model, 1, Vec3(0.0, 0.0, -1.0));
  std::vector<int> held;
  const Body& b = model.mesh.bodies[0];
  for (int n = b.first_node; n < b.first_node + b.n_nodes; ++n) held.push_back(n);
  dcr::DcrSettings settings;
  settings.surfaces = {"block/boundary", "ball/boundary"};

  const auto run = [&](bool probed) {
    dcr::DcrContact contact(model.mesh, settings, held);
    ContactImpulseProbe probe(contact, all_boundary_nodes(model));
    RunOptions opt;
    opt.contact = probed ? static_cast<ContactModel*>(&probe) : &contact;
    opt.time.end_time = 2e-3;
    opt.time.output_interval = 1e-3;
    RigidState end;
    std::vector<Vec3> x;
    opt.on_sample = [&](const State& s) {
      end = s.rigid[0];
      x = s.x;
    };
    REQUIRE(run_explicit(model, opt).verdict == Verdict::completed);
    return std::make_pair(end, x);
  };
  const auto [block_plain, x_plain] = run(false);
  const auto [block_probed, x_probed] = run(true);
  INFO("block velocity without the probe " << block_plain.velocity.transpose() << ", with it "
                                           << block_probed.velocity.transpose());
  CHECK(block_plain.velocity.z() < -1e-3);  // the ball pushed the block down
  CHECK(block_probed.velocity == block_plain.velocity);
  CHECK(block_probed.center == block_plain.center);
  CHECK(x_probed == x_plain);
}
