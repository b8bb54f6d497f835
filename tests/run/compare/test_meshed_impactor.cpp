// Issue 31's evidence for the grid's meshed rigid impactor (docs/rigid-bodies.md, "Flat and
// curved, measured"): at the default grid's four corners (RLS 0.5 and 1.5, KE 10 and 100 J; the
// rigid model does not depend on ER), the rigid model run with the ccm model's meshed sphere made
// rigid (its curved surface, the grid's default) against the analytic sphere: the three final-state
// metrics within 1 % of each other.
//
// At the corner RLS 1.5, KE 10 J the artifact's final kinetic energy is set by a few surface
// nodes touching and leaving the sphere, and the step schedule alone moves the analytic run's by
// 1.4 % (dt_safety 0.6-0.9, measured 7 December 2026): one schedule's difference does not resolve
// 1 %. So each metric's difference is averaged over four schedules (a difference of the models,
// not of one schedule's chatter); each schedule's own difference is held to 1 % plus the analytic
// run's spread over the schedules.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>

#include "run/scene/point_scene.hpp"
#include "run/scene/scene_run.hpp"
#include "study/grid/grid_expand.hpp"
#include "study/grid/grid_file.hpp"
#include "study/metrics/model_errors.hpp"
#include "tests/support/scene_history.hpp"

using namespace ccm;

namespace {

constexpr std::array<const char*, 3> kMetrics = {"u_mean", "u_max", "kinetic_energy"};
constexpr std::array<double, 4> kSchedules = {0.9, 0.8, 0.7, 0.6};

// The artifact's final u_mean, u_max and kinetic energy of a run of `scene`.
std::array<double, 3> final_state(Scene scene) {
  const test::SceneHistory run(std::move(scene));
  std::array<double, 3> out{};
  for (size_t m = 0; m < kMetrics.size(); ++m)
    out[m] = run.column(fmt::format("{}.{}", study::kArtifactBody, kMetrics[m])).back();
  return out;
}

}  // namespace

TEST_CASE(
    "meshed rigid impactor: at the default grid's four corners the final state is the "
    "analytic sphere's within 1 %",
    "[rigid-body][validation]") {
  const study::GridSpec analytic =
      study::parse_grid_file(CCM_SOURCE_DIR "/scenes/grids/default.toml");
  study::GridSpec meshed = analytic;
  meshed.contact.meshed_rigid_impactor = true;
  for (const study::GridPoint& p : study::expand_grid(analytic)) {
    const bool corner = p.modulus_ratio == 1e6 &&
                        (p.length_ratio == 0.5 || p.length_ratio == 1.5) &&
                        (p.kinetic_energy == 10.0 || p.kinetic_energy == 100.0);
    if (!corner) continue;
    std::array<double, 3> mean_difference{}, lowest{}, highest{};
    lowest.fill(std::numeric_limits<double>::infinity());
    highest.fill(-std::numeric_limits<double>::infinity());
    std::array<std::array<double, 3>, kSchedules.size()> difference{};
    for (size_t k = 0; k < kSchedules.size(); ++k) {
      Scene a = study::point_scene(analytic, p, study::ImpactModel::rigid);
      Scene m = study::point_scene(meshed, p, study::ImpactModel::rigid);
      a.time.dt_safety = m.time.dt_safety = kSchedules[k];
      const auto fa = final_state(a), fm = final_state(m);
      for (size_t i = 0; i < kMetrics.size(); ++i) {
        difference[k][i] = (fm[i] - fa[i]) / std::abs(fa[i]);
        mean_difference[i] += difference[k][i] / static_cast<double>(kSchedules.size());
        lowest[i] = std::min(lowest[i], fa[i]);
        highest[i] = std::max(highest[i], fa[i]);
      }
    }
    for (size_t i = 0; i < kMetrics.size(); ++i) {
      const double spread = (highest[i] - lowest[i]) / std::abs(lowest[i]);
      INFO("RLS " << p.length_ratio << ", KE " << p.kinetic_energy << ", " << kMetrics[i]
                  << ": mean difference " << mean_difference[i] << ", the analytic run's spread "
                  << spread);
      CHECK(std::abs(mean_difference[i]) < 0.01);
      for (size_t k = 0; k < kSchedules.size(); ++k)
        CHECK(std::abs(difference[k][i]) < 0.01 + spread);
    }
  }
}
