#include "tests/reports/synthetic_study.hpp"

#include <algorithm>
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

double mesh_scale(const study::GridPoint& p) {
  const auto it = p.other_axes.find("mesh_scale");
  return it == p.other_axes.end() ? 1.0 : it->second;
}

double finest_scale() {
  return *std::min_element(kConvergenceScales.begin(), kConvergenceScales.end());
}

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

// A 2 kg impactor at 1 m/s along -z until contact, then steadily to `rebound` along +z at t_f:
// a constant force m (1 + rebound) / (t_f - t_c) while in contact.
study::ImpactorHistory impactor(const std::vector<double>& time, double rebound) {
  study::ImpactorHistory h;
  h.mass = kSyntheticImpactorMass;
  for (double t : time) {
    h.vx.push_back(0.0);
    h.vy.push_back(0.0);
    h.vz.push_back(-1.0 + (1.0 + rebound) * ramp(t));
  }
  return h;
}

double initial_stable_dt(ImpactModel model, double er, double scale) {
  return model == ImpactModel::ccm ? 1e-4 * scale / std::sqrt(er) : 1e-4 * scale;
}

double average_iteration_seconds(ImpactModel model, double rls, double scale) {
  return (model == ImpactModel::ccm ? 2e-4 : 1e-4 * std::pow(2.0, rls)) / (scale * scale);
}

long steps_until(double t, ImpactModel model, double er, double scale) {
  return std::lround(t / initial_stable_dt(model, er, scale));
}

study::RunRecord run(const study::GridPoint& p, ImpactModel model) {
  const bool ccm = model == ImpactModel::ccm;
  const bool unstable = !ccm && p.index == kUnstablePointIndex;
  const double s = mesh_scale(p), er = p.modulus_ratio;
  study::RunRecord r;
  r.point = p;
  r.model = model;
  r.verdict = unstable ? "unstable" : "completed";
  r.reason = unstable ? kUnstableReason : "";
  r.unstable_time = unstable ? 0.12 : 0.0;
  r.initial_stable_dt = initial_stable_dt(model, er, s);
  r.average_iteration_seconds = average_iteration_seconds(model, p.length_ratio, s);
  r.steps = steps_until(unstable ? 0.12 : kFinalTime, model, er, s);
  r.wall_seconds = r.average_iteration_seconds * static_cast<double>(r.steps);
  r.dt_min = 0.9 * r.initial_stable_dt;
  r.dt_max = r.initial_stable_dt;
  study::MeasuredCost cost;  // every step at ISTS: the measured cost is the thesis's estimate
  cost.step_cpu_seconds = r.wall_seconds;
  cost.step_wall_seconds = r.wall_seconds;
  cost.dt_first = r.initial_stable_dt;
  cost.dt_mean = r.initial_stable_dt;
  cost.steps_structure = r.steps;
  r.cost = cost;
  r.max_energy_error = unstable ? 0.2 : 1e-3;
  r.n_elements = std::lround((ccm ? 2000 : 1000) / (s * s * s));
  r.n_nodes = std::lround((ccm ? 600 : 300) / (s * s * s));
  r.scene_hash = ccm ? "ccmscenehash" : "rigidscenehash";
  r.started_at = "2026-11-22T05:00:00.000Z";
  r.ended_at = "2026-11-22T05:01:00.000Z";
  const double convergence_factor = p.other_axes.contains("mesh_scale") && ccm
                                        ? 1.0 - synthetic_convergence_error(model, er, s)
                                        : 1.0;
  const double factor = (ccm ? 1.0 - synthetic_final_error(er) : 1.0) * convergence_factor;
  r.artifact = history(p, factor, unstable ? 0.12 : kFinalTime);
  r.impactor = impactor(r.artifact.time, ccm ? kSyntheticReboundCcm : kSyntheticReboundRigid);
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

// As study::expand_convergence: each case at each mesh scale, numbered after the grid.
std::vector<study::GridPoint> convergence_points() {
  std::vector<study::GridPoint> points;
  int index = kSyntheticPoints;
  for (const SyntheticCase& c : kConvergenceCases)
    for (double scale : kConvergenceScales)
      points.push_back(
          {index++, c.modulus_ratio, c.length_ratio, c.kinetic_energy, {{"mesh_scale", scale}}});
  return points;
}

}  // namespace

double synthetic_final_error(double modulus_ratio) {
  return 0.4 * (1.0 - std::log10(modulus_ratio) / 6.0);
}

double synthetic_normalised_runtime(ImpactModel model, double modulus_ratio, double length_ratio) {
  return average_iteration_seconds(model, length_ratio, 1.0) /
         initial_stable_dt(model, modulus_ratio, 1.0);
}

double synthetic_wall_seconds(ImpactModel model, double modulus_ratio, double length_ratio,
                              double scale) {
  return average_iteration_seconds(model, length_ratio, scale) *
         static_cast<double>(steps_until(kFinalTime, model, modulus_ratio, scale));
}

double synthetic_convergence_error(ImpactModel model, double modulus_ratio, double scale) {
  return model == ImpactModel::ccm ? 0.1 * (scale - finest_scale())
                                   : synthetic_final_error(modulus_ratio);
}

void write_synthetic_study(const std::filesystem::path& file) {
  db::StudyStore store(file);
  store.open_study("synthetic", "gridhash0123");
  const auto provenance = db::current_provenance("gridhash0123");
  std::vector<study::PointMetrics> grid_metrics;
  for (const auto& [points, is_grid] :
       {std::pair{grid(), true}, std::pair{convergence_points(), false}})
    for (const study::GridPoint& p : points) {
      store.add_grid_point(p);
      const auto ccm_run = run(p, ImpactModel::ccm);
      const auto rigid_run = run(p, ImpactModel::rigid);
      store.record_run(ccm_run, provenance);
      store.record_run(rigid_run, provenance);
      const auto metrics = study::compute_point_metrics(ccm_run, rigid_run);
      store.save_metrics(metrics);
      if (is_grid) grid_metrics.push_back(metrics);
    }
  store.save_fits(study::fit_study(grid_metrics));  // as `ccm study run`: the main grid only
}

}  // namespace ccm::test
