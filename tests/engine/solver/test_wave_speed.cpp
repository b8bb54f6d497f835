// Evidence 5: a stress pulse in a long bar reaches the far end at t = L / c. With nu = 0 the
// bar and dilatational speeds coincide, c = sqrt(E / rho), and there is no lateral dispersion
// to argue about.
#include <catch2/catch.hpp>
#include <cmath>

#include "engine/bc/node_selection.hpp"
#include "tests/support/models.hpp"
#include "tests/support/tolerance.hpp"

using namespace ccm;

TEST_CASE("A force step at one end of a bar arrives at the far end at L / c", "[wave]") {
  const double L = 1.0, w = 0.02, E = 1e6, rho = 1000.0;
  Model model = test::box_model(Vec3(L, w, w), 100, 2, 2, test::neo_hookean(E, 0.0, rho));
  const double c = std::sqrt(E / rho);
  const double force = 1e-3 * E * w * w;  // stress 1e-3 E: strain 1e-3, linear regime
  const double rise = 2e-4;               // ~ 1/150 of L / c
  const auto end = boundary_on_plane(model.mesh, 0, Vec3::Zero(), Vec3::UnitX(), 1e-9);
  model.bcs.loads.push_back(
      make_surface_load("push", model.mesh, end, Vec3::UnitX(),
                        TimeTable({{0.0, 0.0}, {rise, force}, {1.0, force}})));
  const int tip = nearest_node(model.mesh, 0, Vec3(L, w / 2, w / 2));
  HistoryRecorder history(model.mesh, {false, false, false, {{"tip", tip}}});
  RunOptions opt;
  opt.time.end_time = 1.3 * L / c;
  opt.time.output_interval = 1e-5;
  opt.history = &history;
  REQUIRE(run_explicit(model, opt).verdict == Verdict::completed);

  // The step carries particle velocity v0 = sigma / (rho c); the free end moves at 2 v0. The
  // front is taken as the first time the tip's velocity reaches v0 (half its final value),
  // minus half the rise time of the load.
  const double v0 = force / (w * w) / (rho * c);
  double arrival = -1.0;
  for (const auto& row : history.rows())  // columns: time, ux, uy, uz, vx, vy, vz
    if (arrival < 0.0 && row[4] >= v0) arrival = row[0] - 0.5 * rise;
  REQUIRE(arrival > 0.0);
  INFO("arrival " << arrival << " s, L/c = " << L / c << " s");
  CHECK(test::relative_error(arrival, L / c) < 0.03);
}
