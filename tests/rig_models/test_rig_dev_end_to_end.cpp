// End to end on the synthetic dev trials (tests/data/rig-dev, 12 cases x 3 trials): every
// file read and checked (rates and deadband of cases.toml), and the trials of each case compared
// with each other (mean and spread). Skipped with a warning when the folder is not there.
#include <fmt/format.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>

#include "rig_models/cases/case_file.hpp"
#include "rig_models/compare/case_comparison.hpp"
#include "rig_models/measurement/trial_folder.hpp"
#include "rig_models/signal/deadband.hpp"

namespace fs = std::filesystem;
using namespace ccm::rig;

namespace {

// The synthetic trials kept in the repository (tests/data/rig-dev/README.md).
const fs::path kDevData = fs::path(CCM_SOURCE_DIR) / "tests" / "data" / "rig-dev";
const fs::path kCaseFile = fs::path(CCM_SOURCE_DIR) / "rig_models" / "cases.toml";

// Every step of the series equals 1 / rate, to 1e-6 s (timestamps are printed to 1e-7 s).
bool sampled_at(const TimeSeries& s, double rate) {
  for (size_t i = 1; i < s.t.size(); ++i)
    if (std::abs(s.t[i] - s.t[i - 1] - 1.0 / rate) > 1e-6) return false;
  return true;
}

// The fastest impactor velocity up to the contact onset: the impact speed as measured.
double impact_speed(const MeasuredTrial& m, double onset) {
  double v_max = 0.0;
  for (size_t i = 0; i < m.impactor_velocity_mps.t.size(); ++i)
    if (m.impactor_velocity_mps.t[i] <= onset)
      v_max = std::max(v_max, m.impactor_velocity_mps.value[i]);
  return v_max;
}

// The pointwise mean of one channel over the trials (trial_ensemble.hpp).
TimeSeries mean_of(const std::vector<MeasuredTrial>& trials, TimeSeries MeasuredTrial::*member) {
  std::vector<TimeSeries> channel;
  for (const MeasuredTrial& m : trials) channel.push_back(m.*member);
  return channel_ensemble(channel).mean;
}

}  // namespace

TEST_CASE("rig-dev end to end: read every trial, sensor model, trials of a case compared",
          "[rig][rig-dev]") {
  REQUIRE(fs::is_directory(kDevData));
  const RigCaseTable cases = read_case_table(kCaseFile);
  const RigParameters& rig = cases.rig;
  const auto by_case = read_trial_folder(kDevData);  // all read and checked first
  REQUIRE(by_case.size() == cases.cases.size());

  std::cout << "case  trials  impact speed [m/s]  onset [s]         first contact [s]  "
               "peak P [kPa]     V_i nRMSE to mean\n";
  for (const RigCase& rig_case : cases.cases) {
    INFO(rig_case.code);
    REQUIRE(by_case.count(rig_case.code) == 1);
    const std::vector<MeasuredTrial>& trials = by_case.at(rig_case.code);
    REQUIRE(static_cast<double>(trials.size()) == rig.trials_per_case.value);

    std::vector<double> onsets, durations, speeds, peaks;
    for (const MeasuredTrial& m : trials) {
      INFO(m.source.string());
      CHECK(m.warnings.empty());
      // the sensors' rates of cases.toml (thesis 3.3.3, 3.4.1, 3.4.3)
      CHECK(sampled_at(m.impactor_velocity_mps, rig.velocity_rate.value));
      CHECK(sampled_at(m.artifact_angle_deg, rig.angle_rate.value));
      CHECK(sampled_at(m.pressure_kpa, rig.pressure_rate.value));
      // the sensor's deadband changes nothing in a measured pressure: no reading below it
      CHECK(apply_deadband(m.pressure_kpa, rig.sensor_deadband.value).value ==
            m.pressure_kpa.value);
      const auto contact = first_contact(m.pressure_kpa, rig.sensor_deadband.value);
      REQUIRE(contact);
      CHECK(contact->released);
      onsets.push_back(contact->onset);
      durations.push_back(contact->duration);
      speeds.push_back(impact_speed(m, contact->onset));
      peaks.push_back(*std::max_element(m.pressure_kpa.value.begin(), m.pressure_kpa.value.end()));
    }
    const Spread onset = spread_of(onsets);
    const Spread duration = spread_of(durations);
    const Spread speed = spread_of(speeds);
    const Spread peak = spread_of(peaks);
    // the drop distance was tuned per target speed (thesis 3.2.2); the thesis gives the target
    // only, the synthetic rig reaches 82-110 % of it: 20 % bounds a tuned rig's miss
    CHECK(std::abs(speed.mean / rig_case.target_speed.value - 1.0) < 0.2);
    // repeats of one setup: onsets within one and a half pressure samples of each other
    CHECK(onset.std_dev <= 1.5 / rig.pressure_rate.value);

    // each trial against the mean of the case's trials, channel by channel, as a simulation
    // would be compared with them
    const RigChannels mean{mean_of(trials, &MeasuredTrial::impactor_velocity_mps),
                           mean_of(trials, &MeasuredTrial::artifact_angle_deg),
                           mean_of(trials, &MeasuredTrial::pressure_kpa)};
    std::vector<double> v_nrmse, onset_to_mean;
    for (const MeasuredTrial& m : trials) {
      v_nrmse.push_back(
          *compare_channel(m.impactor_velocity_mps, mean.impactor_velocity_mps).nrmse);
      const ContactComparison k =
          compare_contact(m.pressure_kpa, mean.pressure_kpa, rig.sensor_deadband.value);
      // the mean pressure has a contact too
      REQUIRE(k.onset_error);
      onset_to_mean.push_back(*k.onset_error);
    }
    const Spread v_spread = spread_of(v_nrmse);
    // trials of one case agree: no trial's V_i further than 10 % of its range from the mean
    CHECK(v_spread.max < 0.1);
    // the mean pressure's contact within a pressure sample of the trials' mean onset
    CHECK(std::abs(spread_of(onset_to_mean).mean) <= 1.0 / rig.pressure_rate.value);
    std::cout << fmt::format(
        "{}  {:>6}  {:.3f} +- {:.3f}       {:.4f} +- {:.4f}  {:.4f} +- {:.4f}    {:6.1f} +- "
        "{:5.1f}  {:.3f} (max {:.3f})\n",
        rig_case.code, trials.size(), speed.mean, speed.std_dev, onset.mean, onset.std_dev,
        duration.mean, duration.std_dev, peak.mean, peak.std_dev, v_spread.mean, v_spread.max);
  }
}
