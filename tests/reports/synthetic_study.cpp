#include "tests/reports/synthetic_study.hpp"

#include <cmath>
#include <vector>

#include "db/store/study_store.hpp"
#include "study/fit/study_fits.hpp"
#include "study/metrics/point_metrics.hpp"

namespace ccm::test {
namespace {

using study::ImpactModel;

constexpr double kContactTime = 0.1;  // [s]
constexpr double kFinalTime = 0.15;   // [s]
constexpr int kSamples = 31;

// 0 before contact, then linear to 1 at t_f.
double ramp(double t) {
  return t < kContactTime ? 0.0 : (t - kContactTime) / (kFinalTime - kContactTime);
}

study::ArtifactHistory history(const study::GridPoint& p, double factor, double t_end) {
  study::ArtifactHistory h;
  for (int i = 0; i < kSamples; ++i) {
    const double t = kFinalTime * i / (kSamples - 1);
    if (t > t_end + 1e-12) break;
    h.time.push_back(t);
    h.kinetic_energy.push_back(0.5 * p.kinetic_energy * ramp(t) * factor);
    h.u_mean.push_back(1e-3 * ramp(t) * factor);
    h.u_max.push_back(2e-3 * ramp(t) * factor);
  }
  return h;
}

study::RunRecord run(const study::GridPoint& p, ImpactModel model) {
  const bool ccm = model == ImpactModel::ccm;
  const bool unstable = !ccm && p.index == kUnstablePointIndex;
  study::RunRecord r;
  r.point = p;
  r.model = model;
  r.verdict = unstable ? "unstable" : "completed";
  r.reason = unstable ? kUnstableReason : "";
  r.unstable_time = unstable ? 0.12 : 0.0;
  r.initial_stable_dt = ccm ? 1e-4 / std::sqrt(p.modulus_ratio) : 1e-4;
  r.average_iteration_seconds = ccm ? 2e-4 : 1e-4;
  r.steps = std::lround((unstable ? 0.12 : kFinalTime) / r.initial_stable_dt);
  r.wall_seconds = r.average_iteration_seconds * static_cast<double>(r.steps);
  r.dt_min = 0.9 * r.initial_stable_dt;
  r.dt_max = r.initial_stable_dt;
  r.max_energy_error = unstable ? 0.2 : 1e-3;
  r.n_elements = ccm ? 2000 : 1000;
  r.n_nodes = ccm ? 600 : 300;
  r.scene_hash = ccm ? "ccmscenehash" : "rigidscenehash";
  r.started_at = "2026-11-22T05:00:00.000Z";
  r.ended_at = "2026-11-22T05:01:00.000Z";
  const double factor = ccm ? 1.0 - synthetic_final_error(p.modulus_ratio) : 1.0;
  r.artifact = history(p, factor, unstable ? 0.12 : kFinalTime);
  return r;
}

std::vector<study::GridPoint> grid() {
  std::vector<study::GridPoint> points;
  for (double ke : {10.0, 100.0})
    for (double rls : {0.5, 1.0, 1.5})
      for (double er : {1.0, 1e2, 1e4, 1e6})
        points.push_back({static_cast<int>(points.size()), er, rls, ke, {}});
  return points;
}

}  // namespace

double synthetic_final_error(double modulus_ratio) {
  return 0.4 * (1.0 - std::log10(modulus_ratio) / 6.0);
}

void write_synthetic_study(const std::filesystem::path& file) {
  db::StudyStore store(file);
  store.open_study("synthetic", "gridhash0123");
  const auto provenance = db::current_provenance("gridhash0123");
  std::vector<study::PointMetrics> metrics;
  for (const study::GridPoint& p : grid()) {
    store.add_grid_point(p);
    const auto ccm_run = run(p, ImpactModel::ccm);
    const auto rigid_run = run(p, ImpactModel::rigid);
    store.record_run(ccm_run, provenance);
    store.record_run(rigid_run, provenance);
    metrics.push_back(study::compute_point_metrics(ccm_run, rigid_run));
    store.save_metrics(metrics.back());
  }
  store.save_fits(study::fit_study(metrics));
}

}  // namespace ccm::test
