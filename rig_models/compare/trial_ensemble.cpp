#include "rig_models/compare/trial_ensemble.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "rig_models/signal/resample.hpp"

namespace ccm::rig {
namespace {

// The first trial's times that lie inside every trial's span.
std::vector<double> common_times(std::span<const TimeSeries> trials) {
  std::vector<double> times = trials[0].t;
  for (const TimeSeries& trial : trials.subspan(1)) times = times_inside(trial, times);
  return times;
}

}  // namespace

ChannelEnsemble channel_ensemble(std::span<const TimeSeries> trials) {
  if (trials.size() < 2)
    throw std::invalid_argument(
        fmt::format("trial ensemble: {} trial(s), at least 2 needed", trials.size()));
  for (const TimeSeries& trial : trials) check_time_series(trial, "trial channel");
  const std::vector<double> times = common_times(trials);
  if (times.empty()) throw std::invalid_argument("trial ensemble: the trials share no time");
  std::vector<TimeSeries> sampled;
  for (const TimeSeries& trial : trials) sampled.push_back(sample_at(trial, times));
  ChannelEnsemble e{{times, std::vector<double>(times.size())}, std::vector<double>(times.size())};
  std::vector<double> at_k(trials.size());
  for (size_t k = 0; k < times.size(); ++k) {
    for (size_t j = 0; j < sampled.size(); ++j) at_k[j] = sampled[j].value[k];
    const Spread s = spread_of(at_k);
    e.mean.value[k] = s.mean;
    e.spread[k] = s.std_dev;
  }
  return e;
}

Spread spread_of(std::span<const double> values) {
  if (values.empty()) throw std::invalid_argument("spread of no values");
  const double n = static_cast<double>(values.size());
  Spread s;
  s.mean = std::accumulate(values.begin(), values.end(), 0.0) / n;
  double sum_sq = 0.0;
  for (double v : values) sum_sq += (v - s.mean) * (v - s.mean);
  s.std_dev = values.size() > 1 ? std::sqrt(sum_sq / (n - 1.0)) : 0.0;
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  s.min = *lo;
  s.max = *hi;
  return s;
}

ChannelAgainstTrials compare_with_trials(std::span<const TimeSeries> trials,
                                         const TimeSeries& simulated) {
  if (trials.empty()) throw std::invalid_argument("compare with trials: no trial");
  ChannelAgainstTrials out;
  std::vector<double> rmse, peak, peak_time;
  for (const TimeSeries& trial : trials) {
    out.per_trial.push_back(compare_channel(trial, simulated));
    rmse.push_back(out.per_trial.back().rmse);
    peak.push_back(out.per_trial.back().peak_error);
    peak_time.push_back(out.per_trial.back().peak_time_error);
  }
  out.rmse = spread_of(rmse);
  out.peak_error = spread_of(peak);
  out.peak_time_error = spread_of(peak_time);
  return out;
}

}  // namespace ccm::rig
