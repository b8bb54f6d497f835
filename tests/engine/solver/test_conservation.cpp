// Evidence 4: a free body with no external force conserves linear and angular momentum to
// round-off over 10^4 steps, and a vibrating elastic body's total energy does not drift.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "tests/support/models.hpp"
#include "tests/support/tolerance.hpp"

using namespace ccm;

TEST_CASE("Free body: linear and angular momentum conserved over 1e4 steps", "[conservation]") {
  Model model =
      test::box_model(Vec3(0.1, 0.06, 0.04), 4, 3, 2, test::neo_hookean(1e5, 0.4, 1000.0));
  const Vec3 v0(0.3, -0.1, 0.2), omega(1.0, 2.0, -3.0);
  for (size_t i = 0; i < model.initial_velocity.size(); ++i) {
    const Vec3& X = model.mesh.X[i];
    // Translation + rotation + a deformation that keeps the body vibrating and spinning.
    model.initial_velocity[i] =
        v0 + omega.cross(X) + Vec3(0.5 * X.y(), 0.0, -0.8 * X.x() * X.y() * 50);
  }
  Vec3 p0, L0, p1, L1;
  bool first = true;
  RunOptions opt;
  opt.time.end_time = 1.0;  // capped by max_steps below; never reached
  opt.time.output_interval = 0.0;
  const double dt = 0.8 * reference_stable_dt(model.elements, model.mesh.X);
  opt.time.max_dt = dt;
  opt.time.end_time = 10000 * dt;
  opt.on_sample = [&](const State& s) {
    (first ? p0 : p1) = test::linear_momentum(s);
    (first ? L0 : L1) = test::angular_momentum(s);
    first = false;
  };
  const RunSummary r = run_explicit(model, opt);
  REQUIRE(r.verdict == Verdict::completed);
  CHECK(r.steps >= 10000);
  // Internal forces sum to zero and have zero moment (P F^T symmetric) exactly in exact
  // arithmetic; central difference then conserves both exactly. 1e-12 bounds the round-off
  // of 1e4 steps (about 1e-16 per step, accumulating at worst linearly).
  CHECK(test::relative_error(p1, p0) < 1e-12);
  CHECK(test::relative_error(L1, L0) < 1e-12);
}

TEST_CASE("Vibrating cantilever: total energy drifts less than 0.5 % over 1e4 steps",
          "[conservation]") {
  const double L = 0.2;
  Model model = test::box_model(Vec3(L, 0.02, 0.02), 20, 2, 2, test::neo_hookean(1e5, 0.3, 1000.0));
  for (size_t i = 0; i < model.initial_velocity.size(); ++i) {
    const double x = model.mesh.X[i].x();
    model.initial_velocity[i] = Vec3(0.0, 0.0, 0.5 * std::sin(0.5 * std::numbers::pi * x / L));
    if (x < 1e-12) model.bcs.fix({static_cast<int>(i)});
  }
  HistoryRecorder history(model.mesh, {true, true, false, {}});
  RunOptions opt;
  const double dt = 0.9 * reference_stable_dt(model.elements, model.mesh.X);
  opt.time.max_dt = dt;
  opt.time.end_time = 10000 * dt;
  opt.time.output_interval = 100 * dt;
  opt.history = &history;
  const RunSummary r = run_explicit(model, opt);
  REQUIRE(r.verdict == Verdict::completed);
  const auto& rows = history.rows();
  REQUIRE(rows.size() > 50);
  const double E0 = rows.front()[1] + rows.front()[2];
  double worst = 0.0, min_ke = rows.front()[1];
  for (const auto& row : rows) {
    worst = std::max(worst, std::abs(row[1] + row[2] - E0) / E0);
    min_ke = std::min(min_ke, row[1]);
  }
  INFO("max |E - E0| / E0 = " << worst);
  CHECK(min_ke < 0.5 * E0);  // energy really moved between kinetic and strain energy
  CHECK(worst < 0.005);
}
