#include "study/metrics/point_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "study/metrics/impact_metrics.hpp"
#include "study/metrics/model_errors.hpp"
#include "study/metrics/runtime_ratio.hpp"

namespace ccm::study {

namespace {

ModelTiming timing_of(const RunRecord& run) {
  ModelTiming t;
  t.verdict = run.verdict;
  t.steps = run.steps;
  t.wall_seconds = run.wall_seconds;
  t.average_iteration_seconds = run.average_iteration_seconds;
  t.initial_stable_dt = run.initial_stable_dt;
  return t;
}

void require_same_point(const RunRecord& ccm, const RunRecord& rigid) {
  if (ccm.model != ImpactModel::ccm || rigid.model != ImpactModel::rigid)
    throw std::invalid_argument("point metrics need the ccm run first and the rigid run second");
  if (ccm.point.index != rigid.point.index)
    throw std::invalid_argument("point metrics: runs of grid points " +
                                std::to_string(ccm.point.index) + " and " +
                                std::to_string(rigid.point.index) + " cannot be compared");
}

// Empty when the two histories share their sample times, else why not.
std::string sample_mismatch(const ArtifactHistory& c, const ArtifactHistory& r) {
  if (c.time.empty() || c.time.size() != r.time.size())
    return "the runs have different numbers of samples (ccm " + std::to_string(c.time.size()) +
           ", rigid " + std::to_string(r.time.size()) + ")";
  const double tol = 1e-9 * std::max(std::abs(c.time.back()), 1e-300);
  for (std::size_t i = 0; i < c.time.size(); ++i)
    if (std::abs(c.time[i] - r.time[i]) > tol)
      return "sample " + std::to_string(i) + " is at different times in the two runs";
  const std::size_t n = c.time.size();
  for (const ArtifactHistory* h : {&c, &r})
    if (h->u_mean.size() != n || h->u_max.size() != n || h->kinetic_energy.size() != n)
      return "a history series has a different length than its time series";
  return {};
}

std::string unusable_reason(const RunRecord& ccm, const RunRecord& rigid) {
  if (!ccm.completed()) return "ccm run " + ccm.verdict + ": " + ccm.reason;
  if (!rigid.completed()) return "rigid run " + rigid.verdict + ": " + rigid.reason;
  for (const RunRecord* run : {&ccm, &rigid})
    if (!run->cost)
      return std::string(to_string(run->model)) +
             " run: its cost was not measured (stored before store schema 4); run the study "
             "again in a new store to measure it";
  return sample_mismatch(ccm.artifact, rigid.artifact);
}

}  // namespace

PointMetrics compute_point_metrics(const RunRecord& ccm, const RunRecord& rigid) {
  require_same_point(ccm, rigid);
  PointMetrics m;
  m.point = ccm.point;
  m.ccm = timing_of(ccm);
  m.rigid = timing_of(rigid);
  m.excluded_reason = unusable_reason(ccm, rigid);
  if (!m.excluded_reason.empty()) return m;

  const ArtifactHistory& c = ccm.artifact;
  const ArtifactHistory& r = rigid.artifact;
  m.t_final = c.time.back();
  m.cumulative = {cumulative_error(c.time, c.u_mean, r.u_mean),
                  cumulative_error(c.time, c.u_max, r.u_max),
                  cumulative_error(c.time, c.kinetic_energy, r.kinetic_energy)};
  m.final_state = {final_state_error(c.u_mean, r.u_mean), final_state_error(c.u_max, r.u_max),
                   final_state_error(c.kinetic_energy, r.kinetic_energy)};
  for (ModelTiming* t : {&m.ccm, &m.rigid}) {
    t->normalised_runtime = normalised_runtime(t->average_iteration_seconds, t->initial_stable_dt);
    t->total_runtime_thesis_estimate = total_runtime(m.t_final, t->normalised_runtime);
  }
  m.ccm.total_runtime = ccm.cost->step_cpu_seconds;  // measured TR
  m.rigid.total_runtime = rigid.cost->step_cpu_seconds;
  m.runtime_ratio = runtime_ratio(m.ccm.total_runtime, m.rigid.total_runtime);
  m.runtime_ratio_thesis_estimate =
      runtime_ratio(m.ccm.normalised_runtime, m.rigid.normalised_runtime);
  m.weighting = {m.final_state.u_mean / m.runtime_ratio, m.final_state.u_max / m.runtime_ratio,
                 m.final_state.kinetic_energy / m.runtime_ratio};
  m.usable = true;
  m.ccm_impact = impact_quantities(ccm);
  m.rigid_impact = impact_quantities(rigid);
  if (m.ccm_impact && m.rigid_impact)
    m.impact_errors = impact_errors(*m.ccm_impact, *m.rigid_impact);
  return m;
}

}  // namespace ccm::study
