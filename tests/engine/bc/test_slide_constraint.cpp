// The slide constraint (engine/bc/slide_constraint.hpp): nodes held to a line through their
// reference position move only along it, and the rest of the body follows the constrained
// nodes as a continuum.
#include <catch2/catch.hpp>
#include <cmath>

#include "engine/bc/node_selection.hpp"
#include "engine/bc/slide_constraint.hpp"
#include "tests/support/models.hpp"
#include "tests/support/tolerance.hpp"

using namespace ccm;

TEST_CASE("Slide constraint: a block under gravity and a sideways pull slides along its track",
          "[slide]") {
  Model model =
      test::box_model(Vec3(0.04, 0.02, 0.02), 4, 2, 2, test::neo_hookean(1e6, 0.3, 1000.0));
  model.bcs.gravity = Vec3(0.0, 0.0, -9.81);
  const double force = 0.5;  // N along +y on the y = 0 face, plus 0.3 N along x (refused)
  model.bcs.loads.push_back(make_surface_load(
      "pull", model.mesh, boundary_on_plane(model.mesh, 0, Vec3::Zero(), Vec3::UnitY(), 1e-9),
      Vec3(0.6, 1.0, 0.0), TimeTable({{0.0, force * std::sqrt(1.36)}})));
  // Every node on the track: the body can only translate along y.
  std::vector<int> all(static_cast<size_t>(model.mesh.n_nodes()));
  for (int i = 0; i < model.mesh.n_nodes(); ++i) all[static_cast<size_t>(i)] = i;
  SlideConstraint slide(all, Vec3::UnitY());
  RunOptions opt;
  opt.time.end_time = 0.02;
  opt.constraints = {&slide};
  double mass = 0.0, max_off_track = 0.0;
  Vec3 mean_u = Vec3::Zero();
  opt.on_sample = [&](const State& s) {
    mass = 0.0;
    mean_u.setZero();
    for (int i = 0; i < s.n_nodes(); ++i) {
      mass += s.m_lumped[i];
      mean_u += s.m_lumped[i] * (s.x[i] - s.X[i]);
      const Vec3 u = s.x[i] - s.X[i];
      max_off_track = std::max(max_off_track, std::hypot(u.x(), u.z()));
    }
    mean_u /= mass;
  };
  const RunSummary r = run_explicit(model, opt);
  REQUIRE(r.verdict == Verdict::completed);
  // Only the y component of the pull acts: u_y = (F_y / m) t^2 / 2 for the rigid translation
  // (central difference integrates constant acceleration exactly: round-off only).
  const double expected = 0.5 * force / mass * 0.02 * 0.02;
  CHECK(max_off_track == 0.0);
  CHECK(test::relative_error(mean_u.y(), expected) < 1e-9);
}
