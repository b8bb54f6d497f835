// What `ccm rig calibrate` minimises: the mean, over the three channels V_i, theta_a and P, of
// each channel's normalised RMSE averaged over the measured trials (compare/channel_metrics.hpp:
// RMSE / measured range). Normalised, so that m/s, degrees and kPa weigh alike; averaged over
// the trials, so that no single trial is fitted.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "rig_models/compare/case_comparison.hpp"

namespace ccm::rig {

inline constexpr std::string_view kObjectiveName =
    "mean over V_i, theta_a, P of the trials' mean nRMSE";

// None when no channel has a normalised RMSE (every measured channel constant).
std::optional<double> calibration_objective(const CaseComparison& comparison);

// The objective over the trials numbered in `trials` alone (a calibration fitted on some trials
// and scored on the others): each channel's nRMSE averaged over those of them that have one.
std::optional<double> calibration_objective(const CaseComparison& comparison,
                                            const std::vector<int>& trials);

// One channel's nRMSE averaged over the trials that have one; with `in_trials` (per trial of
// the comparison, 1 where it counts), over those alone.
std::optional<double> mean_nrmse(const ChannelAgainstTrials& channel,
                                 const std::vector<char>* in_trials = nullptr);

}  // namespace ccm::rig
