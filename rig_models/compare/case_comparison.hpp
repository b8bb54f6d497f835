// A simulated case against the measured trials it is scored on: each channel (V_i, theta_a, P)
// with the metrics of channel_metrics.hpp per trial and their spread over the trials, V_i
// again inside each trial's measured contact window alone, and the contact onset and duration
// errors from the pressure. Computed by the bench test's path (bench_test/rig_case_scores.hpp:
// the case's mapping over the rig's CSV layout); the types are here, where the store reads them.
//
// Which trials score a run: every trial but the one that drove an open-loop run (unless asked
// for). That trial's V_i is the run's input: F_in = M_i dV_i/dt of it, the start at its V_i and
// the gap from its contact onset (docs/rig-models.md), so its V_i before contact, and its
// onset, are matched by construction; scored against it, the run is scored against itself.
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

// A channel scored inside each trial's measured contact window alone: from the trial's contact
// onset to the end of its first contact event (first_contact on its pressure, the threshold the
// deadband), where the open-loop drive no longer carries the impactor along the measurement.
struct ChannelInContact {
  // In the order of CaseComparison::trials; none where the trial has no contact or fewer than
  // two samples of the channel inside it.
  std::vector<std::optional<ChannelComparison>> per_trial;
  std::optional<Spread> rmse;   // over the trials that have one
  std::optional<Spread> nrmse;  // over the trials that have one (range inside the window)
};

struct CaseComparison {
  std::vector<int> trials;        // the scored trials' numbers: the order of every list below
  ChannelAgainstTrials velocity;  // over the whole run window
  ChannelInContact velocity_in_contact;
  ChannelAgainstTrials angle;
  ChannelAgainstTrials pressure;
  std::vector<ContactComparison> contact;  // per trial
  std::optional<Spread> onset_error;       // s, over the trials where both have contact
  std::optional<Spread> duration_error;    // s
};

// The trials to score a run on: all of `trials` but the one numbered `left_out` (the trial
// that drove an open-loop run), in their order.
std::vector<MeasuredTrial> scored_trials(std::span<const MeasuredTrial> trials,
                                         std::optional<int> left_out);

}  // namespace ccm::rig
