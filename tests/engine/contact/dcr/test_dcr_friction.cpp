// Evidence (contact) 7: a block sliding on a plane under gravity with Coulomb friction mu
// decelerates at mu g (rigid-body closed form: the normal force is the weight m g, the friction
// force mu m g opposes the sliding, so dv/dt = -mu g until the block stops).
//
// The block starts resting on the plane (its bottom 1e-6 m above the plane's top, inside the
// proximity distance of the persistent contacts) and sliding at v0. Its centre-of-mass velocity
// is fitted by least squares over a window that starts after the first transient (the block
// settles under its weight: vertical oscillations of period ~ 4 H / c ~ 1 ms) and ends before
// the block stops. Tolerance: 5 % (the figure); what is left besides the contact
// model is the elastic rocking of the block (the friction at its base tilts it and moves the
// normal force forward), which averages out over the window.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "engine/bc/node_selection.hpp"
#include "engine/contact/dcr/dcr_contact.hpp"
#include "tests/support/models.hpp"
#include "tests/support/tolerance.hpp"
#include "tests/support/two_bodies.hpp"

using namespace ccm;

namespace {

struct Slide {
  std::vector<double> t, vx;  // block centre-of-mass velocity along the sliding direction
  RunSummary summary;
  double max_sweeps = 0;
};

Slide run_slide(double mu, double v0, double end_time) {
  const double g = 9.81, gap = 1e-6;
  const MaterialParams plane_mat = test::neo_hookean(1e7, 0.3, 1000.0);
  const MaterialParams block_mat = test::neo_hookean(1e6, 0.3, 1000.0);
  ModelMesh mesh;
  add_body(mesh, "plane", plane_mat,
           test::translated(structured_box(Vec3(0.06, 0.03, 0.01), 12, 6, 2),
                            Vec3(-0.025, -0.015, -0.01)));
  add_body(
      mesh, "block", block_mat,
      test::translated(structured_box(Vec3(0.02, 0.02, 0.01), 4, 4, 2), Vec3(-0.02, -0.01, gap)));
  Model model = make_model(std::move(mesh));
  model.bcs.fix(nodes_on_plane(model.mesh, 0, Vec3(0, 0, -0.01), Vec3::UnitZ(), 1e-9));
  model.bcs.gravity = Vec3(0.0, 0.0, -g);
  const Body& block = model.mesh.bodies[1];
  for (int n = block.first_node; n < block.first_node + block.n_nodes; ++n)
    model.initial_velocity[static_cast<size_t>(n)] = Vec3(v0, 0.0, 0.0);

  dcr::DcrSettings settings;
  settings.surfaces = {"plane/boundary", "block/boundary"};
  settings.friction = mu;
  dcr::DcrContact contact(model.mesh, settings, model.bcs.fixed_nodes);
  RunOptions opt;
  opt.contact = &contact;
  opt.time.end_time = end_time;
  opt.time.output_interval = 5e-4;
  Slide out;
  opt.on_sample = [&](const State& s) {
    out.t.push_back(s.t);
    out.vx.push_back(test::mean_velocity(s, model.mesh.bodies[1]).x());
    out.max_sweeps = std::max(out.max_sweeps, static_cast<double>(contact.solver_sweeps()));
  };
  out.summary = run_explicit(model, opt);
  return out;
}

// Least-squares slope of y(t) over t in [t0, t1].
double fitted_slope(const std::vector<double>& t, const std::vector<double>& y, double t0,
                    double t1) {
  double n = 0, st = 0, sy = 0, stt = 0, sty = 0;
  for (size_t i = 0; i < t.size(); ++i) {
    if (t[i] < t0 || t[i] > t1) continue;
    n += 1;
    st += t[i];
    sy += y[i];
    stt += t[i] * t[i];
    sty += t[i] * y[i];
  }
  return (n * sty - st * sy) / (n * stt - st * st);
}

}  // namespace

TEST_CASE("DCR friction: a block sliding on a plane decelerates at mu g", "[dcr][friction]") {
  const double mu = 0.3, g = 9.81, v0 = 0.5;
  const Slide r = run_slide(mu, v0, 0.035);
  INFO("verdict " << to_string(r.summary.verdict) << " " << r.summary.instability.reason);
  REQUIRE(r.summary.verdict == Verdict::completed);
  const double decel = -fitted_slope(r.t, r.vx, 0.008, 0.035);
  INFO("deceleration " << decel << " m/s^2, mu g = " << mu * g << ", final v " << r.vx.back()
                       << " m/s, steps " << r.summary.steps << ", max sweeps " << r.max_sweeps
                       << ", energy error " << r.summary.energy_balance_error);
  CHECK(test::relative_error(decel, mu * g) < 0.05);
  // Still sliding at the end (v0 / (mu g) = 0.17 s), so the fit saw only the sliding phase.
  CHECK(r.vx.back() > 0.2 * v0);
  CHECK(r.summary.energy_balance_error < 0.05);
}

TEST_CASE("DCR friction: without friction the block keeps sliding", "[dcr][friction][heavy]") {
  const Slide r = run_slide(0.0, 0.5, 0.02);
  REQUIRE(r.summary.verdict == Verdict::completed);
  // Frictionless contact exerts only normal impulses, so the horizontal momentum of the block
  // changes only through the tilting of the contact normals as the block rocks: well below
  // 1 % of v0 over the run (the friction case loses 12 % in the same time).
  CHECK(std::abs(r.vx.back() - 0.5) < 0.005 * 0.5);
}
