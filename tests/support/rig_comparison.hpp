// A rig comparison for tests that store or draw one: `simulated` taken as the run's curves (its
// pressure the raw one, through a sensor of 1 kPa deadband and a 20 Hz low-pass, which the
// 100 Hz curves of those tests allow), scored by the bench test's path as `ccm rig run` scores.
#pragma once

#include <vector>

#include "bench_test/rig_case_scores.hpp"
#include "rig_models/compare/case_comparison.hpp"

namespace ccm::test {

inline rig::CaseComparison rig_comparison(const std::vector<rig::MeasuredTrial>& trials,
                                          const rig::RigChannels& simulated) {
  return bench::score_rig_case(
      "RX025", trials,
      {simulated.impactor_velocity_mps, simulated.artifact_angle_deg, simulated.pressure_kpa},
      {1.0, 20.0});
}

}  // namespace ccm::test
