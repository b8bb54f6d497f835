#include "study/metrics/convergence.hpp"

#include <limits>
#include <map>
#include <tuple>

#include "study/metrics/model_errors.hpp"

namespace ccm::study {
namespace {

ArtifactErrors final_state_errors(const ArtifactHistory& run, const ArtifactHistory& reference) {
  return {final_state_error(reference.u_mean, run.u_mean),
          final_state_error(reference.u_max, run.u_max),
          final_state_error(reference.kinetic_energy, run.kinetic_energy)};
}

}  // namespace

double mesh_scale(const GridPoint& point) {
  const auto it = point.other_axes.find("mesh_scale");
  return it == point.other_axes.end() ? 1.0 : it->second;
}

std::vector<ConvergenceRow> compare_convergence_runs(const std::vector<RunRecord>& runs) {
  using Key = std::tuple<double, double, double>;
  std::map<Key, const RunRecord*> finest;
  auto key = [](const RunRecord& r) {
    return Key{r.point.modulus_ratio, r.point.length_ratio, r.point.kinetic_energy};
  };
  for (const auto& r : runs) {
    if (r.model != ImpactModel::ccm || !r.completed()) continue;
    auto& best = finest[key(r)];
    if (best == nullptr || mesh_scale(r.point) < mesh_scale(best->point)) best = &r;
  }
  std::vector<ConvergenceRow> rows;
  for (const auto& r : runs) {
    ConvergenceRow row{r.point, r.model, false, false, {}, r.wall_seconds, r.n_elements};
    const auto it = finest.find(key(r));
    if (it != finest.end() && r.completed() &&
        it->second->artifact.time.size() == r.artifact.time.size()) {
      row.reference = it->second == &r;
      row.usable = true;
      row.final_state = final_state_errors(r.artifact, it->second->artifact);
    }
    rows.push_back(row);
  }
  return rows;
}

double accuracy_per_second(const ConvergenceRow& row) {
  return row.wall_seconds > 0.0 ? (1.0 - row.final_state.kinetic_energy) / row.wall_seconds
                                : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace ccm::study
