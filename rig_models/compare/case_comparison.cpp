#include "rig_models/compare/case_comparison.hpp"

namespace ccm::rig {

std::vector<MeasuredTrial> scored_trials(std::span<const MeasuredTrial> trials,
                                         std::optional<int> left_out) {
  std::vector<MeasuredTrial> out;
  for (const MeasuredTrial& m : trials)
    if (!left_out || m.trial != *left_out) out.push_back(m);
  return out;
}

}  // namespace ccm::rig
