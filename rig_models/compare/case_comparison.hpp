// A simulated case against every measured trial of it: each channel (V_i, theta_a, P) with
// the metrics of channel_metrics.hpp per trial and their spread over the trials, and the
// contact onset and duration errors from the pressure.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "rig_models/compare/channel_metrics.hpp"
#include "rig_models/compare/trial_ensemble.hpp"
#include "rig_models/measurement/measured_trial.hpp"

namespace ccm::rig {

// The three rig channels of a simulation, each on its own timestamps (a simulated pressure
// already through the sensor model, rig_channels.hpp).
struct RigChannels {
  TimeSeries impactor_velocity_mps;
  TimeSeries artifact_angle_deg;
  TimeSeries pressure_kpa;
};

struct CaseComparison {
  ChannelAgainstTrials velocity;
  ChannelAgainstTrials angle;
  ChannelAgainstTrials pressure;
  std::vector<ContactComparison> contact;  // per trial
  std::optional<Spread> onset_error;       // s, over the trials where both have contact
  std::optional<Spread> duration_error;    // s
};

// Throws std::invalid_argument when there is no trial or a channel does not overlap.
CaseComparison compare_case(std::span<const MeasuredTrial> trials, const RigChannels& simulated,
                            double contact_threshold_kpa);

}  // namespace ccm::rig
