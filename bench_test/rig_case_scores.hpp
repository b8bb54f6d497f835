// The rig's cases as bench tests (docs/bench-test.md, docs/rig-models.md "Comparison"): each
// case's mapping over the rig's own CSV layout (docs/measurements.md), and a rig run scored
// through the bench test's path, reported in the rig's terms (rig::CaseComparison):
//   velocity             V_i [m/s] over the run window;
//   velocity_in_contact  V_i inside each trial's measured contact (window = "contact");
//   angle                theta_a [deg];
//   pressure             P [kPa]: the simulated raw pressure through the sensor model, its
//                        deadband, then the first-order low-pass at the cutoff (thesis 3.3.3,
//                        apply_to = "simulated": the measured one is the sensor's reading);
//   contact event        the first sample of P at or above the deadband to the first below it.
#pragma once

#include <span>
#include <string>

#include "bench_test/bench_mapping.hpp"
#include "bench_test/bench_trials.hpp"
#include "rig_models/compare/case_comparison.hpp"
#include "rig_models/measurement/measured_trial.hpp"
#include "rig_models/post/rig_channels.hpp"

namespace ccm::bench {

// The mapping file of a case's trials (<CASE>_t*.csv), with the rig's sensor model.
std::string rig_case_mapping_text(const std::string& case_code, const rig::PressureSensor& sensor);

// The same, read by the mapping reader (`file` names it in messages).
BenchMapping rig_case_mapping(const std::string& case_code, const rig::PressureSensor& sensor);

// A trial read by the rig's reader, as the mapping's channels in SI; named by its file, or by
// its place in the list (`index`, 0-based) when it has none.
BenchTrial bench_trial_of(const rig::MeasuredTrial& trial, const BenchMapping& mapping,
                          std::size_t index);

// A run's curves before the sensor model: V_i [m/s], theta_a [deg] and the raw pressure
// P_raw [kPa] (eq. 3.8), each on the run's output clock (the trials' clock).
struct RigRunCurves {
  rig::TimeSeries velocity_mps, angle_deg, pressure_raw_kpa;
};

// The run scored on `trials` (at least one). Throws ScoringError when a channel cannot be
// scored (fewer than kMinRatedSamples measured samples inside the run).
rig::CaseComparison score_rig_case(const std::string& case_code,
                                   std::span<const rig::MeasuredTrial> trials,
                                   const RigRunCurves& run, const rig::PressureSensor& sensor);

}  // namespace ccm::bench
