// The physical drive (rig_models/drive/hanging_weight_drive.hpp): a weight on a string over a
// pulley pulling a block along the track. Checked against the closed forms of the lumped
// system: impulse m_w g t shared by block and weight, a slack string leaves the block coasting,
// and the run-up distance v^2 (M + m_w) / (2 m_w g), with the track's Coulomb and viscous
// friction (the friction's own evidence: tests/engine/bc/test_track_friction.cpp).
#include <catch2/catch.hpp>
#include <cmath>

#include "engine/bc/node_selection.hpp"
#include "rig_models/drive/hanging_weight_drive.hpp"
#include "tests/support/models.hpp"
#include "tests/support/tolerance.hpp"

using namespace ccm;
using namespace ccm::rig;

namespace {

constexpr double kBlockMass = 1.2;  // kg: 0.1 x 0.05 x 0.05 m at 4800 kg/m^3
constexpr double kG = 9.81;

struct Pull {
  RunSummary summary;
  double v_block = 0.0;  // mass-weighted mean velocity along y at the end
  double tension = 0.0, weight_velocity = 0.0;
  bool slack = false;
};

Pull pull(HangingWeightSettings s, double end_time, double v0 = 0.0) {
  Model model = test::box_model(Vec3(0.05, 0.1, 0.05), 1, 2, 1, test::neo_hookean(1e7, 0.3, 4800));
  std::vector<int> all(static_cast<size_t>(model.mesh.n_nodes()));
  for (int i = 0; i < model.mesh.n_nodes(); ++i) {
    all[static_cast<size_t>(i)] = i;
    model.initial_velocity[static_cast<size_t>(i)] = Vec3(0.0, v0, 0.0);
  }
  const auto front = boundary_on_plane(model.mesh, 0, Vec3(0.0, 0.1, 0.0), Vec3::UnitY(), 1e-9);
  s.gravity = kG;
  HangingWeightDrive drive(model.mesh, front, all, Vec3::UnitY(), s);
  RunOptions opt;
  opt.time.end_time = end_time;
  opt.loads = {&drive};
  Pull out;
  opt.on_sample = [&](const State& st) {
    double p = 0.0, m = 0.0;
    for (int i = 0; i < st.n_nodes(); ++i) {
      p += st.m_lumped[i] * st.v[i].y();
      m += st.m_lumped[i];
    }
    out.v_block = p / m;
  };
  out.summary = run_explicit(model, opt);
  out.tension = drive.tension();
  out.weight_velocity = drive.weight_velocity();
  out.slack = drive.slack();
  return out;
}

}  // namespace

TEST_CASE("hanging weight: the weight's impulse m_w g t goes to block and weight", "[rig][drive]") {
  HangingWeightSettings s;  // 0.5 kg, 5000 N/m string, no friction
  s.string_damping = 0.0;
  const double t = 0.2;
  const Pull p = pull(s, t);
  REQUIRE(p.summary.verdict == Verdict::completed);
  const double impulse = s.weight_mass * kG * t;
  // Linear momentum of the pair: the string is internal, the only external force the weight's
  // gravity. The two are integrated half a step apart: O(dt) of ~200 steps, so 1e-2.
  CHECK(test::relative_error(kBlockMass * p.v_block + s.weight_mass * p.weight_velocity, impulse) <
        1e-2);
  // Mean acceleration m_w g / (M + m_w); the string rings at ~20 Hz about it, so 10 %.
  CHECK(test::relative_error(p.v_block / t, s.weight_mass * kG / (kBlockMass + s.weight_mass)) <
        0.10);
  CHECK(!p.slack);
}

TEST_CASE("hanging weight: a block running ahead of the weight slackens the string",
          "[rig][drive]") {
  HangingWeightSettings s;
  const Pull p = pull(s, 0.1, 2.0);  // the weight needs 0.41 s to catch up
  REQUIRE(p.summary.verdict == Verdict::completed);
  CHECK(p.slack);
  CHECK(p.tension == 0.0);
  CHECK(p.v_block == Approx(2.0).epsilon(1e-12));              // coasting, no friction
  CHECK(p.weight_velocity == Approx(kG * 0.1).epsilon(1e-2));  // in free fall
}

TEST_CASE("run-up distance: v^2 (M + m_w) / (2 (m_w g - mu_k N)) against the track's friction",
          "[rig][drive]") {
  HangingWeightSettings s;
  TrackFrictionSpec track;
  track.normal_force = kBlockMass * kG;
  const double v = 0.5;
  // 1e-4 s steps of the lumped system integrate the constant acceleration exactly but for the
  // last partial step: 1e-3.
  CHECK(test::relative_error(run_up_distance(s, track, kBlockMass, v),
                             v * v * (kBlockMass + s.weight_mass) / (2 * s.weight_mass * kG)) <
        1e-3);
  track.mu_s = 0.2;
  track.mu_k = 0.1;  // the pull less mu_k N: 4.905 - 1.177 N
  CHECK(test::relative_error(run_up_distance(s, track, kBlockMass, v),
                             v * v * (kBlockMass + s.weight_mass) /
                                 (2 * (s.weight_mass * kG - 0.1 * kBlockMass * kG))) < 1e-3);
  track.mu_s = 0.5;  // mu_s N = 5.9 N above the 4.9 N pull: never breaks away
  CHECK_THROWS_WITH(run_up_distance(s, track, kBlockMass, v),
                    Catch::Contains("cannot break the impactor away"));
  track.mu_s = track.mu_k = 0.0;
  track.damping = 10.0;  // terminal speed m_w g / c = 0.49 m/s
  CHECK_THROWS_WITH(run_up_distance(s, track, kBlockMass, v),
                    Catch::Contains("cannot bring the impactor to 0.5 m/s"));
}
