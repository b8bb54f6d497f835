#include "bench_test/rig_case_scores.hpp"

#include <fmt/format.h>

#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

#include "bench_test/bench_scores.hpp"
#include "bench_test/units.hpp"
#include "rig_models/measurement/trial_csv.hpp"

namespace ccm::bench {

namespace {

// The mapping's channels (by name) and the rig's curves they read.
constexpr const char* kVelocity = "velocity";
constexpr const char* kVelocityInContact = "velocity_in_contact";
constexpr const char* kAngle = "angle";
constexpr const char* kPressure = "pressure";
constexpr const char* kContact = "contact";

rig::TimeSeries scaled(rig::TimeSeries s, double factor) {
  for (double& v : s.value) v *= factor;
  return s;
}

// A score in the channel's own unit (SI / factor), in the rig's terms.
rig::ChannelComparison in_unit(const ChannelScore& s, double factor) {
  rig::ChannelComparison c;
  c.n_samples = s.samples;
  c.rmse = s.rmse / factor;
  c.nrmse = s.nrmse;
  c.peak_measured = s.peak_measured / factor;
  c.peak_simulated = s.peak_simulated / factor;
  c.peak_error = s.peak_error / factor;
  c.peak_time_error = s.peak_time_error;
  return c;
}

const ChannelResult& channel(const BenchScores& scores, const std::string& name) {
  for (const ChannelResult& c : scores.channels)
    if (c.channel == name) return c;
  throw std::logic_error(fmt::format("the rig's mapping has no channel '{}'", name));
}

// Per trial (every trial scored on the whole run window) and the spread over the trials.
rig::ChannelAgainstTrials against_trials(const ChannelResult& r, double factor) {
  rig::ChannelAgainstTrials out;
  std::vector<double> rmse, peak, peak_time;
  for (const ChannelScore& s : r.trials) {
    out.per_trial.push_back(in_unit(s, factor));
    rmse.push_back(out.per_trial.back().rmse);
    peak.push_back(out.per_trial.back().peak_error);
    peak_time.push_back(out.per_trial.back().peak_time_error);
  }
  out.rmse = rig::spread_of(rmse);
  out.peak_error = rig::spread_of(peak);
  out.peak_time_error = rig::spread_of(peak_time);
  return out;
}

// In trial order, none where the trial was not scored inside its contact.
rig::ChannelInContact in_contact(const ChannelResult& r, const std::vector<std::string>& names,
                                 double factor) {
  rig::ChannelInContact out;
  std::vector<double> rmse, nrmse;
  for (const std::string& name : names) {
    out.per_trial.emplace_back();
    for (const ChannelScore& s : r.trials)
      if (s.against == name) out.per_trial.back() = in_unit(s, factor);
    if (!out.per_trial.back()) continue;
    rmse.push_back(out.per_trial.back()->rmse);
    if (out.per_trial.back()->nrmse) nrmse.push_back(*out.per_trial.back()->nrmse);
  }
  if (!rmse.empty()) out.rmse = rig::spread_of(rmse);
  if (!nrmse.empty()) out.nrmse = rig::spread_of(nrmse);
  return out;
}

// The rig's mapping names every channel it scores (rig_case_mapping_text): a missing one is a
// defect of this file, not of the user's input.
double factor_of(const BenchMapping& m, const char* name) {
  const ChannelSpec* channel = m.channel(name);
  if (channel == nullptr)
    throw std::logic_error(fmt::format("the rig's bench mapping has no channel '{}'", name));
  return channel->si_factor;
}

}  // namespace

std::string rig_case_mapping_text(const std::string& case_code, const rig::PressureSensor& sensor) {
  const double deadband_pa = *si_factor("kPa") * sensor.deadband_kpa;
  return fmt::format(
      R"(# The rig's case {code} as a bench test (bench_test/rig_case_scores.hpp).
[trials]
files = "{code}_t*.csv"
time_column = "{time}"
time_unit = "s"
comment = "#"
sparse = true

[[channels]]
name = "{velocity}"
column = "{velocity_column}"
unit = "m/s"
observable = "rig.impactor_velocity"

[[channels]]
name = "{velocity_in_contact}"
column = "{velocity_column}"
unit = "m/s"
observable = "rig.impactor_velocity"
window = "{contact}"

[[channels]]
name = "{angle}"
column = "{angle_column}"
unit = "deg"
observable = "rig.artifact_angle"

[[channels]]
name = "{pressure}"
column = "{pressure_column}"
unit = "kPa"
observable = "rig.sensor_pressure"
filter = "low_pass"
cutoff = {cutoff:.17g}
deadband = {deadband:.17g}
deadband_first = true
apply_to = "simulated"

[[events]]
name = "{contact}"
channel = "{pressure}"
threshold = {deadband:.17g}
)",
      fmt::arg("code", case_code), fmt::arg("time", rig::kTimeColumn),
      fmt::arg("velocity", kVelocity), fmt::arg("velocity_in_contact", kVelocityInContact),
      fmt::arg("velocity_column", rig::kVelocityColumn), fmt::arg("angle", kAngle),
      fmt::arg("angle_column", rig::kAngleColumn), fmt::arg("pressure", kPressure),
      fmt::arg("pressure_column", rig::kPressureColumn), fmt::arg("contact", kContact),
      fmt::arg("cutoff", sensor.cutoff_hz), fmt::arg("deadband", deadband_pa));
}

BenchMapping rig_case_mapping(const std::string& case_code, const rig::PressureSensor& sensor) {
  return parse_bench_mapping(rig_case_mapping_text(case_code, sensor),
                             fmt::format("rig mapping of {}", case_code));
}

BenchTrial bench_trial_of(const rig::MeasuredTrial& trial, const BenchMapping& mapping,
                          std::size_t index) {
  const std::map<std::string_view, const rig::TimeSeries*> columns = {
      {rig::kVelocityColumn, &trial.impactor_velocity_mps},
      {rig::kAngleColumn, &trial.artifact_angle_deg},
      {rig::kPressureColumn, &trial.pressure_kpa}};
  BenchTrial b;
  // (a trial made in memory has no file: its place names it)
  b.file = trial.source.empty() ? std::filesystem::path(fmt::format("trial {}", index + 1))
                                : trial.source;
  for (const ChannelSpec& c : mapping.channels)
    b.channels[c.name] = scaled(*columns.at(c.column), c.si_factor);
  return b;
}

rig::CaseComparison score_rig_case(const std::string& case_code,
                                   std::span<const rig::MeasuredTrial> trials,
                                   const RigRunCurves& run, const rig::PressureSensor& sensor) {
  if (trials.empty()) throw std::invalid_argument("score rig case: no measured trial");
  const BenchMapping m = rig_case_mapping(case_code, sensor);
  std::vector<BenchTrial> bench_trials;
  for (std::size_t i = 0; i < trials.size(); ++i)
    bench_trials.push_back(bench_trial_of(trials[i], m, i));
  const std::vector<PreparedTrial> prepared = prepare_trials(m, bench_trials);
  const rig::TimeSeries velocity = scaled(run.velocity_mps, factor_of(m, kVelocity));
  const std::map<std::string, rig::TimeSeries> simulated = {
      {kVelocity, velocity},
      {kVelocityInContact, velocity},
      {kAngle, scaled(run.angle_deg, factor_of(m, kAngle))},
      {kPressure, scaled(run.pressure_raw_kpa, factor_of(m, kPressure))}};
  const BenchScores scores = score_bench_test(m, prepared, simulated);

  rig::CaseComparison c;
  std::vector<std::string> names;
  for (const rig::MeasuredTrial& t : trials) c.trials.push_back(t.trial);
  for (const PreparedTrial& p : prepared) names.push_back(p.name);
  c.velocity = against_trials(channel(scores, kVelocity), factor_of(m, kVelocity));
  c.velocity_in_contact =
      in_contact(channel(scores, kVelocityInContact), names, factor_of(m, kVelocityInContact));
  c.angle = against_trials(channel(scores, kAngle), factor_of(m, kAngle));
  c.pressure = against_trials(channel(scores, kPressure), factor_of(m, kPressure));
  c.contact = scores.events.at(0).per_trial;
  std::vector<double> onset, duration;
  for (const rig::ContactComparison& k : c.contact)
    if (k.onset_error) {
      onset.push_back(*k.onset_error);
      duration.push_back(*k.duration_error);
    }
  if (!onset.empty()) {
    c.onset_error = rig::spread_of(onset);
    c.duration_error = rig::spread_of(duration);
  }
  return c;
}

}  // namespace ccm::bench
