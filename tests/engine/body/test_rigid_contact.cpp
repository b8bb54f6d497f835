// Evidence for DCR contact against rigid bodies (engine/body/, docs/rigid-bodies.md "Contact"):
// a soft ball bouncing off a fixed rigid wall rebounds at e times its impact speed, and the
// momentum the wall's force output integrates to is what the ball lost; a ball striking a free
// rigid block keeps the total linear and angular momentum of the two exactly, and the energy
// balance (the block's kinetic energy and the work of the contact on it included) closes.
#include <catch2/catch.hpp>
#include <cmath>

#include "engine/body/rigid_body_model.hpp"
#include "engine/contact/dcr/dcr_contact.hpp"
#include "engine/observe/history.hpp"
#include "tests/support/contact_scenes.hpp"
#include "tests/support/models.hpp"
#include "tests/support/tolerance.hpp"
#include "tests/support/two_bodies.hpp"

using namespace ccm;

namespace {

constexpr double kRadius = 0.01, kGap = 2e-4, kSpeed = 1.0;
// motion = pinned: the block turns about y through the middle of its lower edge at x = -20 mm.
const Vec3 kBlockPinPoint(-0.02, 0.0, -0.01);

// A 40 x 40 x 10 mm block under a soft ball (R = 10 mm, E = 1 MPa) moving down at 1 m/s, 0.2 mm
// above it; the block is rigid with the given motion.
Model ball_on_rigid_block(RigidMotion motion) {
  ModelMesh mesh;
  add_body(
      mesh, "block", test::neo_hookean(1e8, 0.3, 1000.0),
      test::translated(structured_box(Vec3(0.04, 0.04, 0.01), 8, 8, 2), Vec3(-0.02, -0.02, -0.01)));
  add_body(mesh, "ball", test::neo_hookean(1e6, 0.3, 1000.0),
           test::gmsh_sphere(kRadius, 0.003, Vec3(0.002, 0.001, kRadius + kGap)));
  RigidBodyModel block = make_rigid(mesh, 0, motion);
  block.pin = {.point = kBlockPinPoint, .axis = Vec3::UnitY()};  // read only when pinned
  Model model = make_model(std::move(mesh));
  model.rigid_bodies.push_back(block);
  test::set_body_velocity(model, 1, Vec3(0.0, 0.0, -kSpeed));
  return model;
}

std::vector<int> rigid_nodes(const Model& model) {
  std::vector<int> nodes;
  const Body& b = model.mesh.bodies[0];
  for (int n = b.first_node; n < b.first_node + b.n_nodes; ++n) nodes.push_back(n);
  return nodes;
}

struct Bounce {
  RunSummary summary;
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  Vec3 ball_momentum_0 = Vec3::Zero(), ball_momentum_end = Vec3::Zero();
  Vec3 ball_angular_0 = Vec3::Zero(), ball_angular_end = Vec3::Zero();  // about the origin
  RigidState block_end;
  double impact_speed = 0.0, rebound = -1.0;
};

Bounce bounce(RigidMotion motion, double restitution, double end, int threads = 1) {
  const Model model = ball_on_rigid_block(motion);
  dcr::DcrSettings settings;
  settings.surfaces = {"block/boundary", "ball/boundary"};
  settings.restitution = restitution;
  // Chunks of a few items, so that 2 and 3 threads do split the detection of this small scene.
  settings.threads = {threads, 64};
  dcr::DcrContact contact(model.mesh, settings, rigid_nodes(model));
  HistoryRecorder history(model.mesh, {true, false, false, {}});
  RunOptions opt;
  opt.contact = &contact;
  opt.history = &history;
  opt.threads = threads;
  opt.time.end_time = end;
  opt.time.output_interval = 2e-5;
  Bounce out;
  const Body& ball = model.mesh.bodies[1];
  bool started = false, hit = false;
  opt.on_sample = [&](const State& s) {
    Vec3 p = Vec3::Zero(), L = Vec3::Zero();
    for (int n = ball.first_node; n < ball.first_node + ball.n_nodes; ++n) {
      p += s.m_lumped[n] * s.v[n];
      L += s.m_lumped[n] * s.x[n].cross(s.v[n]);
    }
    if (!started) {
      started = true;
      out.ball_momentum_0 = p;
      out.ball_angular_0 = L;
    }
    out.ball_momentum_end = p;
    out.ball_angular_end = L;
    out.block_end = s.rigid[0];
    const double vz = test::mean_velocity(s, ball).z();
    if (!hit && contact.active_contacts() > 0) {
      hit = true;
      out.impact_speed = -vz;
    }
    if (hit && contact.held_contacts() == 0) out.rebound = std::max(out.rebound, vz);
  };
  out.summary = run_explicit(model, opt);
  out.columns = history.columns();
  out.rows = history.rows();
  return out;
}

size_t column(const Bounce& b, const std::string& name) {
  const auto it = std::find(b.columns.begin(), b.columns.end(), name);
  REQUIRE(it != b.columns.end());
  return static_cast<size_t>(it - b.columns.begin());
}

}  // namespace

TEST_CASE(
    "DCR: a soft ball bounces off a fixed rigid wall at e times its impact speed, and the "
    "wall's force output integrates to the momentum the ball lost",
    "[rigid-body][dcr]") {
  const Bounce b = bounce(RigidMotion::fixed, 0.5, 0.008);
  INFO("verdict " << to_string(b.summary.verdict) << " " << b.summary.instability.reason);
  INFO("impact " << b.impact_speed << " m/s, rebound " << b.rebound << " m/s");
  REQUIRE(b.summary.verdict == Verdict::completed);
  REQUIRE(b.impact_speed > 0.99 * kSpeed);
  // As in the deformable drop test (test_dcr_restitution.cpp): Newton's law on the rigid motions
  // at separation; the ball's rotation enters them: 3 %.
  CHECK(test::relative_error(b.rebound, 0.5 * b.impact_speed) < 0.03);
  // The force output's integral (sum of interval means x interval) is the wall's impulse, and
  // that is the momentum the ball lost, to the round-off of sums over 1e4 steps (1e-6 allowed).
  const size_t fz = column(b, "block.contact_force_z"), jz = column(b, "block.contact_impulse_z");
  double integral = 0.0;
  for (size_t k = 1; k < b.rows.size(); ++k)
    integral += b.rows[k][fz] * (b.rows[k][0] - b.rows[k - 1][0]);
  const double ball_lost = -(b.ball_momentum_end - b.ball_momentum_0).z();
  CHECK(std::abs(integral - b.rows.back()[jz]) < 1e-9 * std::abs(ball_lost));
  CHECK(std::abs(b.block_end.contact_impulse.z() - ball_lost) < 1e-6 * std::abs(ball_lost));
  // A fixed wall never moved.
  CHECK(b.block_end.center == ball_on_rigid_block(RigidMotion::fixed).rigid_bodies[0].mass.center);
  CHECK(b.block_end.velocity == Vec3::Zero());
}

TEST_CASE(
    "DCR: a ball striking a free rigid block keeps the total momentum and angular momentum "
    "of the two, and the energy balance closes",
    "[rigid-body][dcr]") {
  const Bounce b = bounce(RigidMotion::free, 1.0, 0.006);
  INFO("verdict " << to_string(b.summary.verdict) << " " << b.summary.instability.reason);
  REQUIRE(b.summary.verdict == Verdict::completed);
  REQUIRE(b.impact_speed > 0.99 * kSpeed);
  const RigidState& block = b.block_end;
  const double m_block = 1000.0 * 0.04 * 0.04 * 0.01;
  // The block has been struck: it moves down.
  CHECK(block.velocity.z() < -0.05 * kSpeed);
  // Linear momentum: the impulses on the block are minus those on the ball, row by row; round-off
  // of 1e4 steps' sums (1e-9 of the initial momentum).
  const Vec3 total_0 = b.ball_momentum_0, total = b.ball_momentum_end + m_block * block.velocity;
  CHECK((total - total_0).norm() < 1e-9 * total_0.norm());
  // Angular momentum about the origin (the ball strikes 2.2 mm off the block's centre, so the
  // block turns): L = L_ball + c x m V + I omega; the block's own spin from the published state.
  const Model model = ball_on_rigid_block(RigidMotion::free);
  const Mat3 R = block.rotation.toRotationMatrix();
  const Mat3 I_world = R * model.rigid_bodies[0].mass.inertia * R.transpose();
  const Vec3 L_block =
      block.center.cross(m_block * block.velocity) + I_world * block.angular_velocity;
  const Vec3 L_total = b.ball_angular_end + L_block;
  CHECK(block.angular_velocity.norm() > 0.0);
  // The contact's impulses and their reactions act at the same nodes, so they exchange angular
  // momentum exactly; what is left is the measure: the leapfrog keeps sum m x_{n+1} x v_{n+1/2},
  // and the end-of-step sum m x x v differs from it by O(dt |v| |p|).
  const double measure = b.summary.dt_max * kSpeed * total_0.norm();
  INFO("angular momentum change " << (L_total - b.ball_angular_0).norm() << " N m s, measure "
                                  << measure);
  CHECK((L_total - b.ball_angular_0).norm() < measure);
  // Energy: the ball's kinetic and strain energy, the block's kinetic energy and the contact's
  // work on both balance as in a deformable pair (the DCR's own tolerance, 1 %).
  CHECK(b.summary.energy_balance_error < 0.01);
}

TEST_CASE("DCR with a free rigid body: the same history bit for bit on 1, 2 and 3 threads",
          "[rigid-body][dcr][threads]") {
  const Bounce one = bounce(RigidMotion::free, 0.5, 0.003, 1);
  REQUIRE(one.summary.verdict == Verdict::completed);
  REQUIRE(one.impact_speed > 0.0);  // the contact happened
  for (int threads : {2, 3}) {
    INFO(threads << " threads");
    const Bounce other = bounce(RigidMotion::free, 0.5, 0.003, threads);
    REQUIRE(other.rows.size() == one.rows.size());
    for (size_t k = 0; k < one.rows.size(); ++k) CHECK(other.rows[k] == one.rows[k]);
  }
}

// A rigid press (prescribed) squeezes a linear-elastic cube onto a fixed rigid base, both
// frictionless: the cube is in uniaxial stress, sigma = E eps, exactly for linear tets under
// uniform strain. The press's contact force (its history column) against E A eps with eps read
// from the cube's nodes; eps against the press's travel. Quasi-static: the press speeds up over
// 10 ms, 2.5 periods of the cube's axial mode (4 ms), which leaves a dynamic part of about 0.5 %
// of the force (rho c v over 1 - cos over the ramp); 2 % allowed.
TEST_CASE(
    "DCR: a prescribed rigid press on a block between frictionless plates gives the "
    "linear-elastic static force",
    "[rigid-body][dcr]") {
  const double L = 0.02, E = 1e5, gap = 1e-5, v = 0.005, t_ramp = 0.01, end = 0.06;
  ModelMesh mesh;
  add_body(mesh, "base", test::neo_hookean(1e9, 0.3, 1000.0),
           test::translated(structured_box(Vec3(0.04, 0.04, 0.01), 4, 4, 1),
                            Vec3(-0.01, -0.01, -0.01 - gap)));
  add_body(mesh, "block", {MaterialModel::linear_elastic, E, 0.3, 1000.0},
           structured_box(Vec3(L, L, L), 4, 4, 4));
  add_body(mesh, "press", test::neo_hookean(1e9, 0.3, 1000.0),
           test::translated(structured_box(Vec3(0.04, 0.04, 0.01), 4, 4, 1),
                            Vec3(-0.01, -0.01, L + gap)));
  const RigidBodyModel base = make_rigid(mesh, 0, RigidMotion::fixed);
  RigidBodyModel press = make_rigid(mesh, 2, RigidMotion::prescribed);
  press.prescribed_velocity[2] = TimeTable({{0.0, 0.0}, {t_ramp, -v}});
  Model model = make_model(std::move(mesh));
  model.rigid_bodies = {base, press};
  std::vector<int> held;
  for (int b : {0, 2})
    for (int n = 0; n < model.mesh.bodies[b].n_nodes; ++n)
      held.push_back(model.mesh.bodies[b].first_node + n);
  dcr::DcrSettings settings;
  settings.surfaces = {"base/boundary", "block/boundary", "press/boundary"};
  dcr::DcrContact contact(model.mesh, settings, held);
  HistoryRecorder history(model.mesh, {false, false, false, {}});
  State last;
  RunOptions opt;
  opt.contact = &contact;
  opt.history = &history;
  opt.time.end_time = end;
  opt.time.output_interval = 1e-3;
  opt.on_sample = [&](const State& s) { last = s; };
  const RunSummary run = run_explicit(model, opt);
  INFO("verdict " << to_string(run.verdict) << " " << run.instability.reason);
  REQUIRE(run.verdict == Verdict::completed);

  const Body& block = model.mesh.bodies[1];
  double top = 0.0, bottom = 0.0;
  int n_top = 0, n_bottom = 0;
  for (int n = block.first_node; n < block.first_node + block.n_nodes; ++n) {
    if (model.mesh.X[n].z() > L - 1e-9) top += last.x[n].z(), ++n_top;
    if (model.mesh.X[n].z() < 1e-9) bottom += last.x[n].z(), ++n_bottom;
  }
  const double eps = 1.0 - (top / n_top - bottom / n_bottom) / L;
  const double travel = v * (end - 0.5 * t_ramp) - 2.0 * gap;
  INFO("strain " << eps << ", from the press's travel " << travel / L);
  // The press's travel less the two gaps is the cube's shortening, to the DCR's kept separation
  // (1e-4 of the shortest edge at each face: 0.1 % of the travel here) and the dynamic part.
  CHECK(std::abs(eps - travel / L) < 0.02 * travel / L);
  const auto& cols = history.columns();
  const size_t fz = static_cast<size_t>(
      std::find(cols.begin(), cols.end(), "press.contact_force_z") - cols.begin());
  REQUIRE(fz < cols.size());
  const double F = history.rows().back()[fz];  // on the press: up, +z
  const double F_static = E * L * L * eps;
  INFO("press force " << F << " N, E A eps " << F_static << " N");
  CHECK(std::abs(F - F_static) < 0.02 * F_static);
}

TEST_CASE(
    "DCR: a ball striking a pinned rigid block keeps the angular momentum about the pin, and the "
    "block turns on it",
    "[rigid-body][dcr]") {
  const Bounce b = bounce(RigidMotion::pinned, 1.0, 0.006);
  INFO("verdict " << to_string(b.summary.verdict) << " " << b.summary.instability.reason);
  REQUIRE(b.summary.verdict == Verdict::completed);
  REQUIRE(b.impact_speed > 0.99 * kSpeed);
  // J about the pin: e^T I_c e + m |d_perp|^2 (RB.7), from the block's mass properties.
  const Model model = ball_on_rigid_block(RigidMotion::pinned);
  const MassProperties& mp = model.rigid_bodies[0].mass;
  const Vec3 e = Vec3::UnitY(), d = mp.center - kBlockPinPoint;
  const Vec3 d_perp = d - d.dot(e) * e;
  const double J = e.dot(mp.inertia * e) + mp.mass * d_perp.squaredNorm();
  const RigidState& block = b.block_end;
  // It turns about the pin only (struck about 22 mm from it), and its centre stays on its circle
  // about the axis.
  CHECK(std::abs(block.angular_velocity.y()) > 0.0);
  CHECK(std::abs(block.angular_velocity.x()) + std::abs(block.angular_velocity.z()) <
        1e-12 * std::abs(block.angular_velocity.y()));
  const Vec3 dc = block.center - kBlockPinPoint;
  CHECK(std::hypot(dc.x(), dc.z()) == Approx(std::hypot(d.x(), d.z())).epsilon(1e-12));
  // Angular momentum about the axis: the ball's (about the origin, moved to the pin) and the
  // block's J w. The pin's reaction has no moment about its axis and the contact's impulses have
  // their reactions at the same nodes; what is left is the leapfrog measure, O(dt |v| |p|) times
  // the lever, as for the free block.
  const auto about_pin = [&](const Vec3& L_origin, const Vec3& p) {
    return e.dot(L_origin - kBlockPinPoint.cross(p));
  };
  const double L0 = about_pin(b.ball_angular_0, b.ball_momentum_0);
  const double L1 =
      about_pin(b.ball_angular_end, b.ball_momentum_end) + J * block.angular_velocity.y();
  const double measure = b.summary.dt_max * kSpeed * b.ball_momentum_0.norm();
  INFO("L0 " << L0 << ", L1 " << L1 << ", measure " << measure);
  CHECK(std::abs(L1 - L0) < measure);
  // The block took angular momentum: the exchange is not empty.
  CHECK(std::abs(J * block.angular_velocity.y()) > 0.1 * std::abs(L0));
  CHECK(b.summary.energy_balance_error < 0.01);
}

TEST_CASE(
    "DCR: a ball bouncing off a free rigid block separates at e times the approach speed, the "
    "block answering with its own mass",
    "[rigid-body][dcr]") {
  // Newton's law on the pair's rigid motions at separation (pair_restitution.hpp), with the
  // block's own mobility (1/M + (r x n)^T I^-1 (r x n)) in it: the relative normal velocity
  // after is e times before. The ball (4.2 g) against the block (16 g): the block takes a quarter
  // of the momentum, so treating it as anchored (as before) would show as a 25 % error.
  const Bounce b = bounce(RigidMotion::free, 0.5, 0.008);
  INFO("verdict " << to_string(b.summary.verdict) << " " << b.summary.instability.reason);
  REQUIRE(b.summary.verdict == Verdict::completed);
  REQUIRE(b.impact_speed > 0.99 * kSpeed);
  const double m_ball = b.ball_momentum_0.norm() / kSpeed;
  const double ball_vz = b.ball_momentum_end.z() / m_ball;
  const double separation = ball_vz - b.block_end.velocity.z();
  INFO("impact " << b.impact_speed << " m/s, separation " << separation << " m/s, block "
                 << b.block_end.velocity.z() << " m/s");
  // As for the fixed wall: the ball's rotation and the block's enter the rigid motions: 3 %.
  CHECK(test::relative_error(separation, 0.5 * b.impact_speed) < 0.03);
  // Momentum is kept through the restitution's impulse too (1e-9, as for e = 1).
  const double m_block = 1000.0 * 0.04 * 0.04 * 0.01;
  const Vec3 total = b.ball_momentum_end + m_block * b.block_end.velocity;
  CHECK((total - b.ball_momentum_0).norm() < 1e-9 * b.ball_momentum_0.norm());
}
