#include "study/metrics/thesis_trends.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ccm::study {

TrendRow thesis_trend(const RunRecord& ccm, const RunRecord& rigid) {
  const ArtifactHistory& c = ccm.artifact;
  const ArtifactHistory& r = rigid.artifact;
  const std::size_t n = c.kinetic_energy.size();
  if (n == 0 || r.kinetic_energy.size() != n || c.u_mean.size() != n || r.u_mean.size() != n ||
      c.u_max.size() != n || r.u_max.size() != n)
    throw std::invalid_argument("thesis trend: the two runs' histories differ in length");
  double gap = 0.0, peak = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    gap = std::max(gap, std::abs(c.kinetic_energy[i] - r.kinetic_energy[i]));
    peak = std::max(peak, r.kinetic_energy[i]);
  }
  if (!(peak > 0.0) || !(r.u_mean.back() > 0.0) || !(r.u_max.back() > 0.0))
    throw std::invalid_argument("thesis trend: the rigid run's artifact does not move");
  TrendRow t;
  t.point = ccm.point;
  t.ke_gap = gap / peak;
  t.ke_ratio = c.kinetic_energy.back() / r.kinetic_energy.back();
  t.u_mean_ratio = c.u_mean.back() / r.u_mean.back();
  t.u_max_ratio = c.u_max.back() / r.u_max.back();
  return t;
}

}  // namespace ccm::study
