// Over the trials of one case: the mean and spread of the measurement, and a simulation
// compared with each trial.
//   mean(t_k)   = (1/n) sum_j m_j(t_k)
//   spread(t_k) = sqrt( sum_j (m_j(t_k) - mean(t_k))^2 / (n - 1) )   (sample standard deviation)
// on the first trial's timestamps that every trial covers (the others interpolated there).
#pragma once

#include <span>
#include <vector>

#include "rig_models/compare/channel_metrics.hpp"
#include "rig_models/signal/time_series.hpp"

namespace ccm::rig {

struct ChannelEnsemble {
  TimeSeries mean;
  std::vector<double> spread;  // at mean.t
};

// Throws std::invalid_argument for fewer than two trials or no common time.
ChannelEnsemble channel_ensemble(std::span<const TimeSeries> trials);

// Mean, sample standard deviation (n - 1), min and max of a set of values (n >= 1; the
// standard deviation is 0 for one value).
struct Spread {
  double mean = 0.0;
  double std_dev = 0.0;
  double min = 0.0;
  double max = 0.0;
};
Spread spread_of(std::span<const double> values);

// A simulation against each trial, and the spread of each metric over the trials.
struct ChannelAgainstTrials {
  std::vector<ChannelComparison> per_trial;
  Spread rmse;
  Spread peak_error;
  Spread peak_time_error;
};
ChannelAgainstTrials compare_with_trials(std::span<const TimeSeries> trials,
                                         const TimeSeries& simulated);

}  // namespace ccm::rig
