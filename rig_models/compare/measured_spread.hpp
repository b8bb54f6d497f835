// How much the measured trials of a case differ from one another, per channel: the mean and
// spread of their peaks, and the RMS over time of their pointwise sample standard deviation
// (trial_ensemble.hpp), with the spread of their contact onsets and durations. The yardstick a
// simulation's error is read against: no model should be expected to sit closer to one trial
// than the trials sit to each other.
#pragma once

#include <optional>
#include <span>

#include "rig_models/compare/trial_ensemble.hpp"
#include "rig_models/measurement/measured_trial.hpp"

namespace ccm::rig {

struct ChannelSpread {
  Spread peak;              // of the trials' peaks (sign kept), channel unit
  double spread_rms = 0.0;  // RMS over the common times of the sample std. dev.; 0 for 1 trial
};

struct MeasuredSpread {
  int n_trials = 0;
  ChannelSpread velocity, angle, pressure;
  std::optional<Spread> onset, duration;  // s, over the trials with a contact
};

// Throws std::invalid_argument when there is no trial.
MeasuredSpread measured_spread(std::span<const MeasuredTrial> trials, double contact_threshold);

}  // namespace ccm::rig
