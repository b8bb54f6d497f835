// Evidence for rigid bodies inside an explicit run (engine/body/rigid_bodies.hpp): a rigid box
// spinning about a principal axis while falling under gravity, beside a deformable box, moves its
// nodes as the closed form says; it adds no stable-step limit however stiff its material; the
// energy balance (its kinetic energy and the work of gravity on it included) closes; a fixed
// rigid body never moves.
#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cmath>

#include "engine/body/rigid_body_model.hpp"
#include "tests/support/models.hpp"

using namespace ccm;

namespace {

const Vec3 kGravity(0.0, 0.0, -9.81);

// A soft 40 mm cube and, 0.1 m above it, a 60 x 40 x 20 mm box of a material a million times
// stiffer (it would set a step a thousand times shorter were it deformable).
ModelMesh two_boxes() {
  ModelMesh mesh;
  add_body(mesh, "soft", test::neo_hookean(1e6, 0.3, 1000.0),
           structured_box(Vec3(0.04, 0.04, 0.04), 4, 4, 4));
  TetMesh hard = structured_box(Vec3(0.06, 0.04, 0.02), 6, 4, 2);
  for (Vec3& x : hard.nodes) x += Vec3(0.0, 0.0, 0.14);
  add_body(mesh, "hard", test::neo_hookean(1e12, 0.3, 7800.0), hard);
  return mesh;
}

RunOptions options(double end) {
  RunOptions o;
  o.time.end_time = end;
  o.time.output_interval = end / 10.0;
  return o;
}

}  // namespace

TEST_CASE(
    "a free rigid body spins and falls as the closed form says, beside a deformable one, "
    "and sets no step",
    "[rigid-body]") {
  const double end = 0.02;
  const Model deformable = make_model(two_boxes());
  ModelMesh mesh = two_boxes();
  RigidBodyModel rigid = make_rigid(mesh, 1, RigidMotion::free);
  const Vec3 v0(0.5, 0.0, 1.0), w0(0.0, 0.0, 40.0);  // about z, a principal axis of the box
  rigid.velocity = v0;
  rigid.angular_velocity = w0;
  Model model = make_model(std::move(mesh));
  model.rigid_bodies.push_back(rigid);
  for (int n = 0; n < model.mesh.bodies[0].n_nodes; ++n) model.initial_velocity[n] = Vec3(0, 0, 0);
  model.bcs.gravity = kGravity;

  State last;
  RunOptions o = options(end);
  o.on_sample = [&](const State& s) { last = s; };
  const RunSummary run = run_explicit(model, o);
  REQUIRE(run.verdict == Verdict::completed);
  RunOptions o_def = options(end);
  o_def.time.max_steps = 1;
  const RunSummary stiff = run_explicit(deformable, o_def);
  // The step is the soft cube's: the hard box deformable would set one sqrt(1e6 x 1000 / 7800)
  // = 358 times shorter (same cell size).
  CHECK(run.dt_initial > 300.0 * stiff.dt_initial);

  // Nodes: x = c0 + v0 t + g t^2/2 + R_z(w t) (X - c0). The leapfrog is exact for the constant
  // acceleration; the Cayley rotation's angle error is at most t w (h w)^2 / 12 with h the
  // longest step (1e-6 rad here), on the 36 mm lever of the corners; twice that is allowed.
  const double w_h = w0.norm() * run.dt_max;
  const double bound = 2.0 * end * w0.norm() * w_h * w_h / 12.0 * 0.037;
  const Vec3 c0 = rigid.mass.center;
  const Mat3 R = Eigen::AngleAxisd(w0.z() * end, Vec3::UnitZ()).toRotationMatrix();
  const Body& hard = model.mesh.bodies[1];
  double worst = 0.0;
  for (int n = hard.first_node; n < hard.first_node + hard.n_nodes; ++n) {
    const Vec3 x = c0 + v0 * end + 0.5 * kGravity * end * end + R * (model.mesh.X[n] - c0);
    worst = std::max(worst, (last.x[n] - x).norm());
    const Vec3 v =
        v0 + kGravity * end + w0.cross(last.x[n] - (c0 + v0 * end + 0.5 * kGravity * end * end));
    CHECK((last.v[n] - v).norm() < 1e-9 + 2.0 * w0.norm() * bound);
  }
  CHECK(worst < bound);
  CHECK(worst > 0.0);  // the bound is not empty: the Cayley angle error is there
  // Its kinetic energy grows by the work of gravity; the balance holds to the deformable cube's
  // round-off (it falls freely too).
  CHECK(run.energy_balance_error < 1e-9);
}

TEST_CASE("a fixed rigid body never moves and carries no mass into the step", "[rigid-body]") {
  ModelMesh mesh = two_boxes();
  RigidBodyModel rigid = make_rigid(mesh, 1, RigidMotion::fixed);
  Model model = make_model(std::move(mesh));
  model.rigid_bodies.push_back(rigid);
  model.bcs.gravity = kGravity;
  State last;
  RunOptions o = options(0.01);
  o.on_sample = [&](const State& s) { last = s; };
  REQUIRE(run_explicit(model, o).verdict == Verdict::completed);
  const Body& hard = model.mesh.bodies[1];
  for (int n = hard.first_node; n < hard.first_node + hard.n_nodes; ++n) {
    CHECK(last.x[n] == model.mesh.X[n]);
    CHECK(last.v[n] == Vec3::Zero());
    CHECK(last.m_lumped[n] == 0.0);
  }
}
