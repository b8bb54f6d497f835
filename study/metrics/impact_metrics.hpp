// What a designer reads of an impact (docs/metrics.md, "The designer's metrics"), from a run's
// impactor and artifact histories at the output samples t_0 .. t_n:
//   peak force        F_peak = max_k m |v_k - v_{k-1}| / (t_k - t_{k-1})               (IM.1)
//                     the mean contact force over each output interval: the impactor's
//                     momentum change (no other force acts on it in a study's scene)
//   indentation       delta_max = max_k u_max(t_k), the artifact's largest displacement  (IM.2)
//   contact duration  T_c = t_last - t_first over the intervals whose force exceeds
//                     kContactForceFraction F_peak (from the first one's start to the last
//                     one's end)                                                         (IM.3)
//   rebound speed     v_r = max(0, -v_n . e), e = v_0 / |v_0|, the approach direction     (IM.4)
// and the rigid run's error against the CCM run, bounded in [0, 1] as the thesis's final-state
// errors are (eqs. 2.37-2.39): |r - c| / max(|r|, |c|) for the first three, and
// |r - c| / |v_0| for the rebound (the approach speed: a rebound of zero is no reason for an
// unbounded error)                                                                      (IM.5)
#pragma once

#include <optional>

#include "records/point_metrics.hpp"
#include "records/run_record.hpp"

namespace ccm::study {

// A force below this fraction of the peak is the contact's noise floor, not contact (IM.3).
inline constexpr double kContactForceFraction = 1e-3;

// The run's quantities, or none when it kept no impactor history (stored before ccm did) or its
// impactor never moved. Throws std::invalid_argument when the histories' lengths differ.
std::optional<ImpactQuantities> impact_quantities(const RunRecord& run);

// IM.5.
ImpactErrors impact_errors(const ImpactQuantities& ccm, const ImpactQuantities& rigid);

}  // namespace ccm::study
