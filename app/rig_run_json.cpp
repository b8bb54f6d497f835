#include "app/rig_run_json.hpp"

#include <array>
#include <utility>

#include "rig_models/calibrate/rig_objective.hpp"

namespace ccm {
namespace {

template <class T>
nlohmann::json optional_json(const std::optional<T>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

nlohmann::json spread_json(const rig::Spread& s) {
  return {{"mean", s.mean}, {"std_dev", s.std_dev}, {"min", s.min}, {"max", s.max}};
}

nlohmann::json optional_spread_json(const std::optional<rig::Spread>& s) {
  return s ? spread_json(*s) : nlohmann::json(nullptr);
}

nlohmann::json channel_json(const rig::ChannelComparison& c, int trial) {
  return {{"trial", trial},
          {"n_samples", c.n_samples},
          {"rmse", c.rmse},
          {"nrmse", optional_json(c.nrmse)},
          {"peak_measured", c.peak_measured},
          {"peak_simulated", c.peak_simulated},
          {"peak_error", c.peak_error},
          {"peak_time_error", c.peak_time_error}};
}

nlohmann::json against_trials_json(const rig::ChannelAgainstTrials& a, const char* unit,
                                   const std::vector<int>& trials,
                                   const rig::ChannelSpread& measured) {
  nlohmann::json per_trial = nlohmann::json::array();
  for (std::size_t k = 0; k < a.per_trial.size(); ++k)
    per_trial.push_back(channel_json(a.per_trial[k], trials.at(k)));
  return {{"unit", unit},
          {"rmse", spread_json(a.rmse)},
          {"nrmse_mean", optional_json(rig::mean_nrmse(a))},
          {"peak_error", spread_json(a.peak_error)},
          {"peak_time_error", spread_json(a.peak_time_error)},
          {"per_trial", per_trial},
          {"measured_peak", spread_json(measured.peak)},
          {"measured_spread_rms", measured.spread_rms}};
}

nlohmann::json window_json(const std::optional<rig::ContactWindow>& w) {
  if (!w) return nullptr;
  return {{"onset", w->onset}, {"duration", w->duration}, {"released", w->released}};
}

nlohmann::json contact_json(const rig::CaseComparison& c) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t k = 0; k < c.contact.size(); ++k) {
    const rig::ContactComparison& k_c = c.contact[k];
    out.push_back({{"trial", c.trials.at(k)},
                   {"measured", window_json(k_c.measured)},
                   {"simulated", window_json(k_c.simulated)},
                   {"onset_error", optional_json(k_c.onset_error)},
                   {"duration_error", optional_json(k_c.duration_error)}});
  }
  return out;
}

nlohmann::json in_contact_json(const rig::ChannelInContact& v, const std::vector<int>& trials) {
  nlohmann::json per_trial = nlohmann::json::array();
  for (std::size_t k = 0; k < v.per_trial.size(); ++k)
    per_trial.push_back(v.per_trial[k] ? channel_json(*v.per_trial[k], trials.at(k))
                                       : nlohmann::json(nullptr));
  return {{"rmse", optional_spread_json(v.rmse)},
          {"nrmse", optional_spread_json(v.nrmse)},
          {"per_trial", per_trial}};
}

nlohmann::json comparison_json(const RigInputs& in, const RigRunOutcome& o) {
  std::vector<int> scored;
  for (const rig::MeasuredTrial& m : in.scored) scored.push_back(m.trial);
  nlohmann::json out = {{"trials", in.trials.size()},
                        {"scored_trials", scored},
                        {"left_out_trial", optional_json(in.left_out)},
                        {"compared", o.comparison.has_value()}};
  if (!o.comparison) return out;
  const rig::CaseComparison& c = *o.comparison;
  const rig::MeasuredSpread& m = *o.measured;
  out["channels"] = {{"velocity", against_trials_json(c.velocity, "m/s", c.trials, m.velocity)},
                     {"angle", against_trials_json(c.angle, "deg", c.trials, m.angle)},
                     {"pressure", against_trials_json(c.pressure, "kPa", c.trials, m.pressure)}};
  out["velocity_in_contact"] = in_contact_json(c.velocity_in_contact, c.trials);
  out["contact"] = contact_json(c);
  out["onset_error"] = optional_spread_json(c.onset_error);
  out["duration_error"] = optional_spread_json(c.duration_error);
  out["measured_onset"] = optional_spread_json(m.onset);
  out["measured_duration"] = optional_spread_json(m.duration);
  out["objective"] = optional_json(o.objective);
  out["objective_name"] = rig::kObjectiveName;
  return out;
}

nlohmann::json model_json(const rig::RigModelFacts& m) {
  nlohmann::json parts = nlohmann::json::array();
  for (const rig::RigPart& p : m.parts)
    parts.push_back({{"name", p.name},
                     {"elements", p.elements},
                     {"mass", p.mass},
                     {"rho", p.material.rho},
                     {"E", p.material.E},
                     {"density_source", p.density_source}});
  return {{"n_elements", m.n_elements},
          {"n_nodes", m.n_nodes},
          {"impactor_mass", m.impactor_mass},
          {"artifact_mass", m.artifact_mass},
          {"artifact_inertia", m.artifact_inertia},
          {"sensor_area", m.sensor_area},
          {"sensor_mesh_area", m.sensor_mesh_area},
          {"frictional_pin", m.frictional_pin},
          {"clamp_stiffness", m.clamp_stiffness},
          {"clamp_damping", m.clamp_damping},
          {"parts", parts}};
}

nlohmann::json run_summary_json(const RunSummary& s, const rig::RunWindow& w) {
  nlohmann::json out = {{"status", to_string(s.verdict)},
                        {"steps", s.steps},
                        {"dt_initial", s.dt_initial},
                        {"dt_min", s.dt_min},
                        {"dt_max", s.dt_max},
                        {"wall_seconds", s.wall_seconds},
                        {"max_energy_error", s.energy_balance_error},
                        {"reason", nullptr},
                        {"unstable_time", nullptr}};
  if (s.verdict == Verdict::unstable) {
    out["reason"] = s.instability.reason;
    out["unstable_time"] = w.start + s.instability.time;  // trial time, as rig_runs stores it
  }
  return out;
}

}  // namespace

nlohmann::json rig_run_json(const RigInputs& in, const RigRunOutcome& o, const RigCommonArgs& args,
                            long long run_id, int exit_code) {
  const rig::RigRunResult& r = o.result;
  const rig::RigCase& c = *in.rig_case;
  nlohmann::json trial = nullptr;
  if (in.drive_trial)
    trial = {{"trial", in.drive_trial->trial}, {"file", in.drive_trial->source.string()}};
  return {{"case_code", c.code},
          {"impactor", rig::name_of(c.impactor)},
          {"artifact", rig::name_of(c.artifact)},
          {"target_speed", c.target_speed.value},
          {"drive", rig::name_of(in.drive)},
          {"drive_trial", trial},
          {"parameters", parameter_text(o.parameters, c)},
          {"mesh_scale", args.mesh_scale},
          {"window",
           {{"start", r.window.start},
            {"end", r.window.end},
            {"gap", r.window.gap},
            {"initial_velocity", r.window.initial_velocity},
            {"measured_onset", optional_json(r.window.measured_onset)}}},
          {"model", model_json(r.model)},
          {"run", run_summary_json(r.summary, r.window)},
          {"comparison", in.trials.empty() ? nlohmann::json(nullptr) : comparison_json(in, o)},
          {"started_at", o.started_at},
          {"ended_at", o.ended_at},
          {"db", in.db.string()},
          {"rig_runs_id", run_id},
          {"files", args.out ? nlohmann::json(args.out->string()) : nlohmann::json(nullptr)},
          {"exit_code", exit_code}};
}

}  // namespace ccm
