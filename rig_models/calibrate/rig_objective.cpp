#include "rig_models/calibrate/rig_objective.hpp"

namespace ccm::rig {

std::optional<double> mean_nrmse(const ChannelAgainstTrials& channel) {
  double sum = 0.0;
  int n = 0;
  for (const ChannelComparison& c : channel.per_trial)
    if (c.nrmse) {
      sum += *c.nrmse;
      ++n;
    }
  if (n == 0) return std::nullopt;
  return sum / n;
}

std::optional<double> calibration_objective(const CaseComparison& comparison) {
  double sum = 0.0;
  int n = 0;
  for (const ChannelAgainstTrials* c :
       {&comparison.velocity, &comparison.angle, &comparison.pressure})
    if (const auto e = mean_nrmse(*c)) {
      sum += *e;
      ++n;
    }
  if (n == 0) return std::nullopt;
  return sum / n;
}

}  // namespace ccm::rig
