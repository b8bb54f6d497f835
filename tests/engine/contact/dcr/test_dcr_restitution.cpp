// Evidence (contact) 3: the coefficient of restitution e acts on the drop test an engineer
// knows (docs/contact-restitution.md). A soft sphere (R = 10 mm, E = 1 MPa) hits a block 100 times
// stiffer, clamped at its base, at v0 = 1 m/s. Rebound speed: the largest upward velocity of the
// sphere's centre of mass once the impact is over, from t_hit + 2 t_c to the end (t_c = 3.1 ms,
// Hertz for this sphere on this block; the measured contact lasts 2.7 ms).
//  - e = 0, dropped under gravity: no rebound (the issue: below 5 % of the impact speed);
//  - e = 0.5, without gravity (so that nothing but the contact changes the velocity): the
//    restitution impulse sets the separating rigid velocity to e times the approach at
//    separation; within 3 % (the sphere's rotation and the block's motion at the contact point,
//    both small, enter the rigid motions of R1);
//  - e = 1: the elastic result, close to v0 because t_c is long against the sphere's fundamental
//    period (~0.5 ms) and little energy is left in vibration; never above v0 (the restitution
//    model never adds energy).
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "engine/bc/node_selection.hpp"
#include "engine/contact/dcr/dcr_contact.hpp"
#include "tests/support/contact_scenes.hpp"
#include "tests/support/models.hpp"
#include "tests/support/tolerance.hpp"

using namespace ccm;

namespace {

// Hertz duration of the sphere on the block (Johnson 11.4), for the end of the impact.
double hertz_duration(double m, double R, double E_ball, double E_block, double nu, double v0) {
  const double E_eff = 1.0 / ((1 - nu * nu) / E_ball + (1 - nu * nu) / E_block);
  return 2.868 * std::pow(m * m / (R * E_eff * E_eff * v0), 0.2);
}

struct Drop {
  double impact_speed = 0.0;  // downward centre-of-mass speed at the first contact
  double rebound = 0.0;       // largest upward centre-of-mass velocity once the impact is over
  int corrections = 0;
  RunSummary summary;
};

Drop run_drop(double restitution, bool gravity) {
  const double R = 0.01, gap = 2e-4, v0 = 1.0, E_ball = 1e6, E_block = 1e8, nu = 0.3;
  ModelMesh mesh;
  add_body(
      mesh, "block", test::neo_hookean(1e8, 0.3, 1000.0),
      test::translated(structured_box(Vec3(0.04, 0.04, 0.01), 8, 8, 2), Vec3(-0.02, -0.02, -0.01)));
  add_body(mesh, "ball", test::neo_hookean(E_ball, nu, 1000.0),
           test::gmsh_sphere(R, 0.003, Vec3(0.0, 0.0, R + gap)));
  Model model = make_model(std::move(mesh));
  model.bcs.fix(nodes_on_plane(model.mesh, 0, Vec3(0, 0, -0.01), Vec3::UnitZ(), 1e-9));
  if (gravity) model.bcs.gravity = Vec3(0.0, 0.0, -9.81);
  test::set_body_velocity(model, 1, Vec3(0.0, 0.0, -v0));

  dcr::DcrSettings settings;
  settings.surfaces = {"block/boundary", "ball/boundary"};
  settings.restitution = restitution;
  dcr::DcrContact contact(model.mesh, settings, model.bcs.fixed_nodes);
  RunOptions opt;
  opt.contact = &contact;
  const double mass = 4.0 / 3.0 * std::numbers::pi * R * R * R * 1000.0;
  const double t_c = hertz_duration(mass, R, E_ball, E_block, nu, v0);
  opt.time.end_time = gap / v0 + 2.6 * t_c;
  opt.time.output_interval = 2e-5;
  Drop out;
  out.rebound = -v0;
  bool hit = false;
  double t_hit = 0.0;
  opt.on_sample = [&](const State& s) {
    const double vz = test::mean_velocity(s, model.mesh.bodies[1]).z();
    if (!hit && contact.active_contacts() > 0) {
      hit = true;
      t_hit = s.t;
      out.impact_speed = -vz;
    }
    if (hit && s.t >= t_hit + 2 * t_c) out.rebound = std::max(out.rebound, vz);
  };
  out.summary = run_explicit(model, opt);
  out.corrections = contact.restitution().corrections();
  return out;
}

}  // namespace

TEST_CASE("DCR restitution: e = 0, a sphere dropped on a stiff block does not rebound",
          "[dcr][restitution]") {
  const Drop r = run_drop(0.0, true);
  INFO("verdict " << to_string(r.summary.verdict) << " " << r.summary.instability.reason);
  INFO("impact " << r.impact_speed << " m/s, rebound " << r.rebound << " m/s, corrections "
                 << r.corrections << ", energy error " << r.summary.energy_balance_error);
  REQUIRE(r.summary.verdict == Verdict::completed);
  REQUIRE(r.impact_speed > 0.9);
  CHECK(r.rebound < 0.05 * r.impact_speed);
  CHECK(r.corrections >= 1);
}

TEST_CASE("DCR restitution: e = 0.5 rebounds at half the impact speed",
          "[dcr][restitution][heavy]") {
  const Drop r = run_drop(0.5, false);
  INFO("verdict " << to_string(r.summary.verdict) << " " << r.summary.instability.reason);
  INFO("impact " << r.impact_speed << " m/s, rebound " << r.rebound << " m/s");
  REQUIRE(r.summary.verdict == Verdict::completed);
  CHECK(test::relative_error(r.rebound, 0.5 * r.impact_speed) < 0.03);
}

TEST_CASE("DCR restitution: e = 1 keeps the elastic rebound", "[dcr][restitution][heavy]") {
  const Drop r = run_drop(1.0, false);
  INFO("verdict " << to_string(r.summary.verdict) << " " << r.summary.instability.reason);
  INFO("impact " << r.impact_speed << " m/s, rebound " << r.rebound << " m/s");
  REQUIRE(r.summary.verdict == Verdict::completed);
  CHECK(r.rebound > 0.85 * r.impact_speed);
  CHECK(r.rebound < r.impact_speed);
  CHECK(r.summary.energy_balance_error < 0.05);
}
