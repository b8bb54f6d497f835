#include "run/runner/point_runner.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/body/mass_properties.hpp"
#include "engine/observe/history.hpp"
#include "records/content_hash.hpp"
#include "records/provenance/timestamp.hpp"
#include "run/runner/study_scene.hpp"
#include "run/scene/scene_run.hpp"

namespace ccm::study {
namespace {

using SystemClock = std::chrono::system_clock;

size_t column_index(const HistoryRecorder& history, const std::string& name) {
  const std::vector<std::string>& cols = history.columns();
  const auto it = std::find(cols.begin(), cols.end(), name);
  if (it == cols.end()) throw std::logic_error(fmt::format("history has no column '{}'", name));
  return static_cast<size_t>(it - cols.begin());
}

ArtifactHistory artifact_history(const HistoryRecorder& history, const std::string& body) {
  const size_t t = column_index(history, "time");
  const size_t ke = column_index(history, body + ".kinetic_energy");
  const size_t u_mean = column_index(history, body + ".u_mean");
  const size_t u_max = column_index(history, body + ".u_max");
  ArtifactHistory h;
  for (const std::vector<double>& row : history.rows()) {
    h.time.push_back(row[t]);
    h.kinetic_energy.push_back(row[ke]);
    h.u_mean.push_back(row[u_mean]);
    h.u_max.push_back(row[u_max]);
  }
  return h;
}

// The impactor's centre-of-mass velocity columns (a deformable or meshed rigid body's
// <name>.vx, an analytic sphere's <name>.sphere_vx) and its mass; empty when the scene has no
// such columns.
ImpactorHistory impactor_history(const HistoryRecorder& history, const SceneRun& run,
                                 const std::string& name) {
  const std::vector<std::string>& cols = history.columns();
  const auto has = [&](const std::string& c) {
    return std::find(cols.begin(), cols.end(), c) != cols.end();
  };
  const std::string prefix = has(name + ".vx") ? name + "." : name + ".sphere_";
  if (!has(prefix + "vx")) return {};
  ImpactorHistory h;
  for (const Body& b : run.model.mesh.bodies)
    if (b.name == name) {
      const std::vector<Tet> tets(run.model.mesh.tets.begin() + b.first_element,
                                  run.model.mesh.tets.begin() + b.first_element + b.n_elements);
      h.mass = tet_mass_properties(tets, run.model.mesh.X, b.material.rho).mass;
    }
  for (const ContactSpec& c : run.scene.contacts)
    if (c.kind == ContactKind::rigid_penalty && !c.rigid && c.sphere.name == name)
      h.mass = c.sphere.mass;
  const size_t x = column_index(history, prefix + "vx"), y = column_index(history, prefix + "vy"),
               z = column_index(history, prefix + "vz");
  for (const std::vector<double>& row : history.rows()) {
    h.vx.push_back(row[x]);
    h.vy.push_back(row[y]);
    h.vz.push_back(row[z]);
  }
  return h;
}

void record_summary(const RunSummary& s, RunRecord& r) {
  r.verdict = std::string(to_string(s.verdict));
  if (s.verdict == Verdict::unstable) {
    r.reason = s.instability.reason;
    r.unstable_time = s.instability.time;
  }
  r.steps = s.steps;
  r.wall_seconds = s.wall_seconds;
  r.initial_stable_dt = s.dt_initial;  // ISTS, eq. 2.42
  r.average_iteration_seconds =
      s.steps > 0 ? s.step_cpu_seconds / static_cast<double>(s.steps) : 0.0;  // AIR, eq. 2.41
  MeasuredCost c;
  c.step_cpu_seconds = s.step_cpu_seconds;
  c.step_wall_seconds = s.step_wall_seconds;
  c.dt_first = s.dt_first;
  c.dt_mean = s.dt_mean;
  c.steps_structure = s.limiters.structure;
  c.steps_contact = s.limiters.contact;
  c.steps_max_dt = s.limiters.max_dt;
  c.steps_landing = s.limiters.landing;
  if (s.limiters.contact > 0) c.dt_contact_min = s.dt_contact_min;
  r.cost = c;
  r.dt_min = s.dt_min;
  r.dt_max = s.dt_max;
  r.max_energy_error = s.energy_balance_error;
  r.n_elements = s.n_elements;
  r.n_nodes = s.n_nodes;
}

}  // namespace

RunRecord run_point(const GridSpec& spec, const GridPoint& point, ImpactModel model,
                    const PointRunOptions& options) {
  RunRecord r;
  r.point = point;
  r.model = model;
  r.started_at = utc_timestamp(SystemClock::now());
  std::string identity = study_run_identity(spec, point, model);
  Scene point_scene = study_scene(spec, point, model);
  if (options.end.fixed) {
    point_scene.time.end = *options.end.fixed;
    point_scene.time.end_after_separation.reset();
    identity += fmt::format("\n# end {}", *options.end.fixed);
  } else if (options.end.earliest > 0.0) {
    identity += fmt::format("\n# earliest_end {}", options.end.earliest);
  }
  r.scene_hash = fnv1a64(identity);
  const SceneRun scene = assemble_scene_run(std::move(point_scene));
  HistoryRecorder history(scene.model.mesh, scene.output);
  RunOptions run = scene_run_options(scene, &history);
  run.time.earliest_end = options.end.earliest;
  run.progress_seconds = options.progress_seconds;
  if (options.progress)
    run.progress = [&](const Progress& p) { options.progress(point, model, p); };
  record_summary(run_explicit(scene.model, run), r);
  r.artifact = artifact_history(history, study_artifact(spec, scene.scene));
  r.impactor = impactor_history(history, scene, study_impactor(spec));
  r.ended_at = utc_timestamp(SystemClock::now());
  return r;
}

}  // namespace ccm::study
