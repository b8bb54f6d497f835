#include "rig_models/calibrate/rig_objective.hpp"

#include <algorithm>

namespace ccm::rig {

std::optional<double> mean_nrmse(const ChannelAgainstTrials& channel,
                                 const std::vector<char>* in_trials) {
  double sum = 0.0;
  int n = 0;
  for (size_t k = 0; k < channel.per_trial.size(); ++k) {
    const ChannelComparison& c = channel.per_trial[k];
    if (in_trials && !(*in_trials)[k]) continue;
    if (c.nrmse) {
      sum += *c.nrmse;
      ++n;
    }
  }
  if (n == 0) return std::nullopt;
  return sum / n;
}

namespace {

std::optional<double> objective_of(const CaseComparison& comparison,
                                   const std::vector<char>* in_trials) {
  double sum = 0.0;
  int n = 0;
  for (const ChannelAgainstTrials* c :
       {&comparison.velocity, &comparison.angle, &comparison.pressure})
    if (const auto e = mean_nrmse(*c, in_trials)) {
      sum += *e;
      ++n;
    }
  if (n == 0) return std::nullopt;
  return sum / n;
}

}  // namespace

std::optional<double> calibration_objective(const CaseComparison& comparison) {
  return objective_of(comparison, nullptr);
}

std::optional<double> calibration_objective(const CaseComparison& comparison,
                                            const std::vector<int>& trials) {
  std::vector<char> in(comparison.trials.size(), 0);
  for (size_t k = 0; k < in.size(); ++k)
    in[k] = std::find(trials.begin(), trials.end(), comparison.trials[k]) != trials.end();
  return objective_of(comparison, &in);
}

}  // namespace ccm::rig
