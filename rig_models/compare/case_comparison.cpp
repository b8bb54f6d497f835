#include "rig_models/compare/case_comparison.hpp"

#include <stdexcept>

namespace ccm::rig {
namespace {

std::vector<TimeSeries> channel_of(std::span<const MeasuredTrial> trials,
                                   TimeSeries MeasuredTrial::*member) {
  std::vector<TimeSeries> out;
  for (const MeasuredTrial& m : trials) out.push_back(m.*member);
  return out;
}

ChannelInContact velocity_in_contact(std::span<const MeasuredTrial> trials,
                                     const TimeSeries& simulated, double threshold) {
  ChannelInContact out;
  std::vector<double> rmse, nrmse;
  for (const MeasuredTrial& m : trials) {
    const auto window = first_contact(m.pressure_kpa, threshold);
    out.per_trial.push_back(window ? compare_channel_within(m.impactor_velocity_mps, simulated,
                                                            window->onset,
                                                            window->onset + window->duration)
                                   : std::nullopt);
    if (!out.per_trial.back()) continue;
    rmse.push_back(out.per_trial.back()->rmse);
    if (out.per_trial.back()->nrmse) nrmse.push_back(*out.per_trial.back()->nrmse);
  }
  if (!rmse.empty()) out.rmse = spread_of(rmse);
  if (!nrmse.empty()) out.nrmse = spread_of(nrmse);
  return out;
}

}  // namespace

CaseComparison compare_case(std::span<const MeasuredTrial> trials, const RigChannels& simulated,
                            double contact_threshold_kpa) {
  if (trials.empty()) throw std::invalid_argument("compare case: no measured trial");
  CaseComparison c;
  for (const MeasuredTrial& m : trials) c.trials.push_back(m.trial);
  c.velocity = compare_with_trials(channel_of(trials, &MeasuredTrial::impactor_velocity_mps),
                                   simulated.impactor_velocity_mps);
  c.velocity_in_contact =
      velocity_in_contact(trials, simulated.impactor_velocity_mps, contact_threshold_kpa);
  c.angle = compare_with_trials(channel_of(trials, &MeasuredTrial::artifact_angle_deg),
                                simulated.artifact_angle_deg);
  c.pressure =
      compare_with_trials(channel_of(trials, &MeasuredTrial::pressure_kpa), simulated.pressure_kpa);
  std::vector<double> onset, duration;
  for (const MeasuredTrial& m : trials) {
    c.contact.push_back(
        compare_contact(m.pressure_kpa, simulated.pressure_kpa, contact_threshold_kpa));
    if (c.contact.back().onset_error) {
      onset.push_back(*c.contact.back().onset_error);
      duration.push_back(*c.contact.back().duration_error);
    }
  }
  if (!onset.empty()) {
    c.onset_error = spread_of(onset);
    c.duration_error = spread_of(duration);
  }
  return c;
}

std::vector<MeasuredTrial> scored_trials(std::span<const MeasuredTrial> trials,
                                         std::optional<int> left_out) {
  std::vector<MeasuredTrial> out;
  for (const MeasuredTrial& m : trials)
    if (!left_out || m.trial != *left_out) out.push_back(m);
  return out;
}

}  // namespace ccm::rig
