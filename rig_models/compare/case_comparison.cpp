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

}  // namespace

CaseComparison compare_case(std::span<const MeasuredTrial> trials, const RigChannels& simulated,
                            double contact_threshold_kpa) {
  if (trials.empty()) throw std::invalid_argument("compare case: no measured trial");
  CaseComparison c;
  c.velocity = compare_with_trials(channel_of(trials, &MeasuredTrial::impactor_velocity_mps),
                                   simulated.impactor_velocity_mps);
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

}  // namespace ccm::rig
