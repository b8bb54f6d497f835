#include "study/metrics/impact_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "engine/core/types.hpp"

namespace ccm::study {
namespace {

Vec3 velocity_at(const ImpactorHistory& h, std::size_t k) { return {h.vx[k], h.vy[k], h.vz[k]}; }

// |r - c| / max(|r|, |c|), 0 when both are 0.
double bounded_error(double c, double r) {
  const double scale = std::max(std::abs(c), std::abs(r));
  return scale > 0.0 ? std::abs(r - c) / scale : 0.0;
}

}  // namespace

std::optional<ImpactQuantities> impact_quantities(const RunRecord& run) {
  const ImpactorHistory& h = run.impactor;
  const std::vector<double>& t = run.artifact.time;
  if (h.empty()) return std::nullopt;
  if (h.vx.size() != t.size() || h.vy.size() != t.size() || h.vz.size() != t.size() ||
      run.artifact.u_max.size() != t.size())
    throw std::invalid_argument(
        "impact metrics: the impactor's and the artifact's histories "
        "have different numbers of samples");
  ImpactQuantities q;
  q.approach_speed = velocity_at(h, 0).norm();
  if (!(q.approach_speed > 0.0)) return std::nullopt;
  std::vector<double> force(t.size(), 0.0);  // force[k]: over (t_{k-1}, t_k]
  for (std::size_t k = 1; k < t.size(); ++k) {
    const double span = t[k] - t[k - 1];
    if (span > 0.0) force[k] = h.mass * (velocity_at(h, k) - velocity_at(h, k - 1)).norm() / span;
    q.peak_force = std::max(q.peak_force, force[k]);  // IM.1
  }
  q.indentation = *std::max_element(run.artifact.u_max.begin(), run.artifact.u_max.end());
  std::optional<std::size_t> first, last;  // IM.3
  for (std::size_t k = 1; k < t.size(); ++k)
    if (q.peak_force > 0.0 && force[k] > kContactForceFraction * q.peak_force) {
      if (!first) first = k;
      last = k;
    }
  if (first) q.contact_duration = t[*last] - t[*first - 1];
  const Vec3 approach = velocity_at(h, 0) / q.approach_speed;
  q.rebound_speed = std::max(0.0, -velocity_at(h, t.size() - 1).dot(approach));  // IM.4
  return q;
}

ImpactErrors impact_errors(const ImpactQuantities& ccm, const ImpactQuantities& rigid) {
  ImpactErrors e;
  e.peak_force = bounded_error(ccm.peak_force, rigid.peak_force);
  e.indentation = bounded_error(ccm.indentation, rigid.indentation);
  e.contact_duration = bounded_error(ccm.contact_duration, rigid.contact_duration);
  e.rebound_speed = ccm.approach_speed > 0.0
                        ? std::abs(rigid.rebound_speed - ccm.rebound_speed) / ccm.approach_speed
                        : 0.0;
  return e;
}

}  // namespace ccm::study
