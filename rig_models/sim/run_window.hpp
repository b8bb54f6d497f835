// Where a rig run starts and ends, where the impactor starts (its gap to the envelope) and how
// fast, from the drive and the measured trial that drives it (thesis 3.3.2).
//   open loop: from `lead` before the trial's measured contact onset (or --start) to the end of
//              the trial (or --end), the impactor at the smoothed measured V_i of the start,
//              its gap the distance that velocity covers until the onset. Starting there is the
//              open-loop drive's own result: before contact it makes the impactor follow V_i.
//   physical:  from the release (t = 0, at rest) to the end of the trial (or --end), the gap the
//              distance the measured V_i covers until the onset; without a trial, the gap the
//              weight needs to bring the impactor to the case's target speed (run_up_distance)
//              and the end `after_contact` after that.
// Every end is rounded down to a whole number of output intervals (the low-pass needs uniform
// samples).
#pragma once

#include <optional>

#include "rig_models/cases/rig_case.hpp"
#include "rig_models/drive/hanging_weight_drive.hpp"
#include "rig_models/measurement/measured_trial.hpp"
#include "rig_models/sim/run_parameters.hpp"

namespace ccm::rig {

struct RunWindow {
  double start = 0.0;                    // s, trial time of the simulation's t = 0
  double end = 0.0;                      // s, trial time
  double gap = 0.0;                      // m
  double initial_velocity = 0.0;         // m/s along the track
  std::optional<double> measured_onset;  // s, the trial's contact onset
};

struct WindowRequest {
  DriveKind drive = DriveKind::open_loop;
  const MeasuredTrial* trial = nullptr;
  std::optional<double> start, end;  // s, trial time
};

// The trial's measured contact onset: the first pressure reading at or above `threshold` [kPa],
// trial time [s]. Throws std::invalid_argument naming the file when there is none.
double measured_onset(const MeasuredTrial& trial, double threshold);

// Throws std::invalid_argument (a user's mistake, with what to do) when the open-loop drive has
// no trial, a physical run is given a start, the trial has no contact above the deadband, or
// the window is empty or outside the trial.
RunWindow run_window(const RigCaseTable& table, const RigCase& c, const WindowRequest& request,
                     const HangingWeightSettings& weight, const TrackFrictionSpec& track);

}  // namespace ccm::rig
