// Scoring a simulation against a bench test's trials (docs/bench-test.md): each trial's channels
// resampled to a uniform clock at the trial's own median step, filtered and deadbanded; each
// trial's clock aligned with the simulation's (a trigger or given offsets); the simulated curve
// resampled at the measured rate, filtered and deadbanded alike, and compared on the measured
// samples inside the channel's window — against every trial and against the trials' mean curve:
// nRMSE, peak and time-of-peak errors as the rig compares (rig_models/compare/channel_metrics.hpp)
// and the ISO/TS 18571 rating (correlate/iso18571_rating.hpp) with the measurement as reference.
#pragma once

#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench_test/bench_mapping.hpp"
#include "bench_test/bench_trials.hpp"
#include "correlate/iso18571_rating.hpp"
#include "rig_models/compare/channel_metrics.hpp"
#include "rig_models/signal/time_series.hpp"

namespace ccm::bench {

// A trial's channels on a uniform clock, filtered, deadbanded; and where its trigger fired.
struct PreparedTrial {
  std::string name;  // the file's name
  // s, each channel's uniform sample interval (its median step: sensors may differ in rate).
  std::map<std::string, double> steps;
  std::map<std::string, rig::TimeSeries> channels;  // on the trial's own clock
  std::optional<double> trigger_time;               // s, own clock
};

// Throws ConfigError naming the trial file and the mapping's align key when a trigger channel
// never reaches its threshold, or a filter cannot be applied at the trial's rate.
std::vector<PreparedTrial> prepare_trials(const BenchMapping& mapping,
                                          const std::vector<BenchTrial>& trials);

struct ChannelScore {
  std::string against;  // a trial's file name, or "mean"
  std::size_t samples = 0;
  double rmse = 0.0;            // SI
  std::optional<double> nrmse;  // none for a constant measured curve
  double peak_measured = 0.0, peak_simulated = 0.0;
  double peak_error = 0.0;       // simulated - measured
  double peak_time_error = 0.0;  // s
  // From kMinRatedSamples samples on (a channel scored inside each trial's event window may hold
  // fewer: a contact of 20 ms sampled at 100 Hz), of a measured curve that is not zero everywhere.
  std::optional<correlate::CurveRating> rating;
};

inline constexpr std::size_t kMinRatedSamples = 10;
inline constexpr std::size_t kMinScoredSamples = 2;  // an RMSE and a range need two

// The curves compared, on the mean's samples: for plots and CSV.
struct ChannelCurves {
  std::vector<double> t, simulated, mean, low, high;  // low, high: the trials' spread
};

struct ChannelResult {
  std::string channel;
  // In trial order; inside an event's windows, only the trials with the event and two samples in
  // it.
  std::vector<ChannelScore> trials;
  std::optional<ChannelScore> mean;  // none inside an event that no trial has
  ChannelCurves curves;
};

// An event ([[events]]) in each trial and in the simulation sampled at the trial's instants.
struct EventResult {
  std::string event;
  std::vector<std::string> trials;                // file names, in trial order
  std::vector<rig::ContactComparison> per_trial;  // onset, duration and their errors
};

struct BenchScores {
  std::vector<double> clock_shifts;  // s, added to each trial's clock
  std::vector<ChannelResult> channels;
  std::vector<EventResult> events;
};

// A simulation that cannot be scored against the trials (not bad input: the run decides it).
struct ScoringError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The scores of `simulated` (one curve per channel, by name, on the simulation's clock). Throws
// ScoringError when the simulated trigger channel never reaches the threshold, or when a
// channel's window (of numbers, or the whole span) holds fewer than kMinScoredSamples measured
// samples inside the simulated span.
BenchScores score_bench_test(const BenchMapping& mapping, const std::vector<PreparedTrial>& trials,
                             const std::map<std::string, rig::TimeSeries>& simulated);

}  // namespace ccm::bench
