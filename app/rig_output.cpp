#include "app/rig_output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <stdexcept>

#include "app/output_file.hpp"
#include "app/setup_time.hpp"
#include "bench_test/bench_scores.hpp"
#include "bench_test/rig_case_scores.hpp"
#include "records/provenance/version.hpp"
#include "rig_models/calibrate/rig_objective.hpp"

namespace ccm {
namespace {

namespace fs = std::filesystem;

std::string case_title(const rig::RigCase& c) {
  return fmt::format("{} ({} impactor, {} artifact, {:.2f} m/s)", c.code, name_of(c.impactor),
                     name_of(c.artifact), c.target_speed.value);
}

std::string pm(const rig::Spread& s, const char* format = "{:.4g}") {
  return fmt::format(fmt::runtime(std::string(format) + " +- " + format), s.mean, s.std_dev);
}

std::string instability(const Instability& i) {
  std::string s = fmt::format("at t = {:.6g} s of the run: {}", i.time, i.reason);
  if (i.element >= 0) s += fmt::format(" (element {})", i.element);
  if (i.node >= 0) s += fmt::format(" (node {})", i.node);
  return s;
}

// summary.toml's [comparison]: which trials scored the run and each channel's mean RMSE and
// nRMSE over them, V_i also inside the measured contact windows.
// How the artifact hangs on its pin (3.3.2, PJ.1).
std::string pin_description(const rig::RigModelFacts& m) {
  std::string s =
      m.frictional_pin ? "on a pin with friction (eq. 3.2-3.6)" : "on a frictionless pin";
  if (m.clamp_stiffness > 0.0)
    s += fmt::format(", clamped: {:.4g} N m/rad, {:.4g} N m s/rad (PJ.1)", m.clamp_stiffness,
                     m.clamp_damping);
  return s;
}

std::string comparison_toml(const RigInputs& in, const RigRunOutcome& o) {
  std::vector<int> scored;
  for (const rig::MeasuredTrial& m : in.scored) scored.push_back(m.trial);
  std::string t = fmt::format("\n[comparison]\nscored_trials = [{}]\n", fmt::join(scored, ", "));
  if (in.left_out) t += fmt::format("left_out_trial = {}\n", *in.left_out);
  if (!o.comparison) return t;
  const rig::CaseComparison& c = *o.comparison;
  const std::array<std::pair<const char*, const rig::ChannelAgainstTrials*>, 3> channels = {
      std::pair{"velocity", &c.velocity}, std::pair{"angle", &c.angle},
      std::pair{"pressure", &c.pressure}};
  for (const auto& [name, a] : channels) {
    t += fmt::format("{}_rmse = {}\n", name, toml_float(a->rmse.mean));
    if (const auto n = rig::mean_nrmse(*a))
      t += fmt::format("{}_nrmse = {}\n", name, toml_float(*n));
  }
  const rig::ChannelInContact& vc = c.velocity_in_contact;
  if (vc.rmse) t += fmt::format("velocity_in_contact_rmse = {}\n", toml_float(vc.rmse->mean));
  if (vc.nrmse) t += fmt::format("velocity_in_contact_nrmse = {}\n", toml_float(vc.nrmse->mean));
  return t;
}

}  // namespace

std::string scored_trials_text(const RigInputs& in) {
  std::vector<int> numbers;
  for (const rig::MeasuredTrial& m : in.scored) numbers.push_back(m.trial);
  std::string t = numbers.empty() ? "no trial"
                                  : fmt::format("{} {}", numbers.size() == 1 ? "trial" : "trials",
                                                fmt::join(numbers, ", "));
  if (in.left_out)
    t += fmt::format(" (trial {} drives the run and is left out; --score-drive-trial scores it)",
                     *in.left_out);
  else if (in.drive == rig::DriveKind::open_loop && in.drive_trial)
    t += fmt::format(" (trial {} drives the run and is scored: --score-drive-trial)",
                     in.drive_trial->trial);
  return t;
}

void compare_with_trials(const RigInputs& in, RigRunOutcome& o) {
  // A run that went unstable early may hold too few samples to compare: then it is not compared,
  // and says why. It is scored on in.scored through the bench test's path (the case's mapping
  // over the rig's CSV layout, bench_test/rig_case_scores.hpp); the trials' own spread is that
  // of every trial.
  const rig::RawHistories& raw = o.result.raw;
  if (in.scored.empty() || raw.t.size() < 2) return;
  const double threshold = in.cases.rig.sensor_deadband.value;
  const rig::PressureSensor sensor{threshold, in.cases.rig.low_pass_cutoff.value};
  try {
    o.comparison = bench::score_rig_case(
        in.rig_case->code, in.scored,
        {{raw.t, raw.impactor_velocity}, {raw.t, raw.angle_deg}, {raw.t, raw.pressure_kpa}},
        sensor);
  } catch (const bench::ScoringError& e) {
    fmt::print(stderr, "ccm: the run is not compared with the trials: {}\n", e.what());
    return;
  }
  o.measured = rig::measured_spread(in.trials, threshold);
  o.objective = rig::calibration_objective(*o.comparison);
}

std::string run_table(const RigInputs& in, const RigRunOutcome& o) {
  const rig::RigRunResult& r = o.result;
  const RunSummary& s = r.summary;
  const rig::RigModelFacts& m = r.model;
  const rig::RigCase& c = *in.rig_case;
  std::string t = fmt::format("ccm rig run {}\n", case_title(c));
  auto row = [&t](std::string_view name, const std::string& value) {
    t += fmt::format("  {:<15}{}\n", name, value);
  };
  row("drive", in.drive_trial
                   ? fmt::format("{}, trial {} ({})", name_of(in.drive), in.drive_trial->trial,
                                 in.drive_trial->source.filename().string())
                   : std::string(name_of(in.drive)));
  row("parameters", rig::describe(o.parameters, c, in.drive));
  row("window", fmt::format("{:.4f} .. {:.4f} s{}", r.window.start, r.window.end,
                            r.window.measured_onset ? fmt::format(" (measured contact at {:.4f} s)",
                                                                  *r.window.measured_onset)
                                                    : std::string()));
  row("impactor", fmt::format("gap {:.3f} mm, initial speed {:.4g} m/s, mass {:.4g} kg",
                              1e3 * r.window.gap, r.window.initial_velocity, m.impactor_mass));
  row("artifact",
      fmt::format("mass {:.4g} kg, J {:.4g} kg m^2 about the pin, centre of mass "
                  "{:.4g} m below it; {}",
                  m.artifact_mass, m.artifact_inertia, m.artifact_cm_depth, pin_description(m)));
  row("sensor",
      fmt::format("A_p {:.4g} m^2 (meshed patch {:.4g} m^2)", m.sensor_area, m.sensor_mesh_area));
  if (c.impactor == rig::ImpactorKind::flexible)
    row("spring",
        fmt::format("E_s {:.6g} Pa (eq. 3.1, K_s {:g} N/m)", m.spring_modulus, m.spring_stiffness));
  row("mesh", fmt::format("{} elements, {} nodes", m.n_elements, m.n_nodes));
  for (const rig::RigPart& p : m.parts)
    row("", fmt::format("{:<11} {:>5} el., {:.4g} kg, rho {:.5g} kg/m^3 ({}), E {:.4g} Pa", p.name,
                        p.elements, p.mass, p.material.rho,
                        p.density_source.starts_with("tuned") ? "tuned" : "given", p.material.E));
  row("set-up", setup_time_text(o.setup_seconds, o.meshing));
  row("steps", fmt::format("{}", s.steps));
  row("dt", fmt::format("initial {:.4g} s, min {:.4g} s, max {:.4g} s", s.dt_initial, s.dt_min,
                        s.dt_max));
  row("wall time",
      fmt::format("{:.2f} s ({:.1f} ns per element-step)", s.wall_seconds, s.ns_per_element_step));
  row("energy error",
      fmt::format("{:.3g} % (largest energy-balance error)", 100.0 * s.energy_balance_error));
  row("verdict", std::string(to_string(s.verdict)));
  if (s.verdict == Verdict::unstable) row("instability", instability(s.instability));
  if (r.open_loop_masked > 0)
    row("drive rule",
        fmt::format("{} F_in samples set to 0 while P > 0 (3.3.2)", r.open_loop_masked));
  return t;
}

std::string comparison_table(const RigInputs& in, const RigRunOutcome& o) {
  if (in.trials.empty()) return {};
  if (in.scored.empty()) return fmt::format("  not scored: {}\n", scored_trials_text(in));
  if (!o.comparison)
    return "  not compared: the run holds fewer than two measured timestamps of a channel\n";
  const rig::CaseComparison& c = *o.comparison;
  const rig::MeasuredSpread& m = *o.measured;
  std::string t = fmt::format(
      "Simulation scored on {}: mean +- sample std. dev. over them; trial spread over all {}\n",
      scored_trials_text(in), in.trials.size());
  t += fmt::format("  {:<8} {:<4} {:>20} {:>7} {:>10} {:>20} {:>20} {:>18} {:>13}\n", "channel",
                   "unit", "RMSE", "nRMSE", "peak sim", "peak measured", "peak error",
                   "peak time err [s]", "trial spread");
  const std::array<std::tuple<const char*, const char*, const rig::ChannelAgainstTrials*,
                              const rig::ChannelSpread*>,
                   3>
      rows = {std::tuple{"V_i", "m/s", &c.velocity, &m.velocity},
              std::tuple{"theta_a", "deg", &c.angle, &m.angle},
              std::tuple{"P", "kPa", &c.pressure, &m.pressure}};
  for (const auto& [name, unit, a, spread] : rows) {
    const auto nrmse = rig::mean_nrmse(*a);
    t += fmt::format("  {:<8} {:<4} {:>20} {:>7} {:>10.4g} {:>20} {:>20} {:>18} {:>13.4g}\n", name,
                     unit, pm(a->rmse), nrmse ? fmt::format("{:.3f}", *nrmse) : "-",
                     a->per_trial.front().peak_simulated, pm(spread->peak), pm(a->peak_error),
                     pm(a->peak_time_error, "{:.4f}"), spread->spread_rms);
  }
  const rig::ChannelInContact& vc = c.velocity_in_contact;
  const auto n_windows = std::count_if(vc.per_trial.begin(), vc.per_trial.end(),
                                       [](const auto& p) { return p.has_value(); });
  if (vc.rmse)
    t += fmt::format(
        "  V_i inside each trial's measured contact window alone: RMSE {} m/s, nRMSE {} ({} of "
        "{} trials)\n",
        pm(*vc.rmse), vc.nrmse ? fmt::format("{:.3f}", vc.nrmse->mean) : "-", n_windows,
        vc.per_trial.size());
  else
    t += "  V_i inside the contact windows: none (no measured contact with two V_i samples)\n";
  if (c.onset_error)
    t += fmt::format(
        "  contact onset error {} s, duration error {} s ({} trials with contact in "
        "both)\n",
        pm(*c.onset_error, "{:.4f}"), pm(*c.duration_error, "{:.4f}"),
        std::count_if(c.contact.begin(), c.contact.end(),
                      [](const rig::ContactComparison& k) { return k.onset_error.has_value(); }));
  else
    t += "  contact: none in the simulation's sensed pressure or in the trials\n";
  if (m.onset)
    t += fmt::format("  measured contact onset {} s, duration {} s\n", pm(*m.onset, "{:.4f}"),
                     pm(*m.duration, "{:.4f}"));
  if (o.objective) t += fmt::format("  objective ({}) {:.4f}\n", rig::kObjectiveName, *o.objective);
  return t;
}

db::RigRunRecord store_record(const RigInputs& in, const RigRunOutcome& o,
                              const RigCommonArgs& args, std::string_view purpose) {
  const rig::RigRunResult& r = o.result;
  const RunSummary& s = r.summary;
  db::RigRunRecord rec;
  db::RigRunRow& w = rec.row;
  w.case_code = in.rig_case->code;
  w.drive = std::string(name_of(in.drive));
  if (in.drive_trial) w.drive_trial = in.drive_trial->trial;
  w.parameters = parameter_text(o.parameters, *in.rig_case);
  w.purpose = std::string(purpose);
  w.status = std::string(to_string(s.verdict));
  if (s.verdict == Verdict::unstable) {
    w.reason = s.instability.reason;
    w.unstable_time = r.window.start + s.instability.time;
  }
  w.window_start = r.window.start;
  w.window_end = r.window.end;
  w.gap = r.window.gap;
  w.initial_velocity = r.window.initial_velocity;
  w.mesh_scale = args.mesh_scale;
  w.n_elements = r.model.n_elements;
  w.n_nodes = r.model.n_nodes;
  w.steps = s.steps;
  if (s.steps > 0) {
    w.dt_initial = s.dt_initial;
    w.dt_min = s.dt_min;
    w.dt_max = s.dt_max;
  }
  w.wall_seconds = s.wall_seconds;
  w.max_energy_error = s.energy_balance_error;
  w.impactor_mass = r.model.impactor_mass;
  w.artifact_mass = r.model.artifact_mass;
  w.artifact_inertia = r.model.artifact_inertia;
  w.sensor_area = r.model.sensor_area;
  w.sensor_mesh_area = r.model.sensor_mesh_area;
  w.objective = o.objective;
  w.cases_hash = in.cases_hash;
  w.geometry_hash = in.geometry_hash;
  if (args.data) w.data_dir = fs::absolute(*args.data).lexically_normal().string();
  w.data_hash = in.data_hash;
  w.started_at = o.started_at;
  w.ended_at = o.ended_at;
  for (const rig::MeasuredTrial& m : in.trials) {
    rec.trials.push_back(m.trial);
    rec.measured_channels.push_back(
        {m.impactor_velocity_mps, m.artifact_angle_deg, m.pressure_kpa});
  }
  rec.comparison = o.comparison;
  rec.measured = o.measured;
  rec.channels = r.channels;
  return rec;
}

void write_run_files(const fs::path& out, const RigInputs& in, const RigRunOutcome& o,
                     const RigCommonArgs& args, int exit_code) {
  fs::create_directories(out);
  const rig::RigRunResult& r = o.result;
  std::string channels = "channel,time_s,value\n";
  const std::array<std::pair<const char*, const rig::TimeSeries*>, 3> series = {
      std::pair{"impactor_velocity_mps", &r.channels.impactor_velocity_mps},
      std::pair{"artifact_angle_deg", &r.channels.artifact_angle_deg},
      std::pair{"pressure_kpa", &r.channels.pressure_kpa}};
  for (const auto& [name, s] : series)
    for (size_t k = 0; k < s->t.size(); ++k)
      channels += fmt::format("{},{},{}\n", name, s->t[k], s->value[k]);
  write_atomic(out / "channels.csv", channels);
  std::string history =
      "time_s,impactor_velocity_mps,artifact_angle_deg,contact_force_n,pin_angle_rad\n";
  for (size_t k = 0; k < r.raw.t.size(); ++k)
    history += fmt::format("{},{},{},{},{}\n", r.raw.t[k], r.raw.impactor_velocity[k],
                           r.raw.angle_deg[k], r.raw.contact_force[k], r.raw.pin_angle[k]);
  write_atomic(out / "history.csv", history);
  const RunSummary& s = r.summary;
  std::string t = "# ccm rig run summary\n";
  t += fmt::format("ccm_version = {}\ncase = {}\ndrive = {}\n", toml_string(version_string()),
                   toml_string(in.rig_case->code), toml_string(name_of(in.drive)));
  if (in.drive_trial)
    t += fmt::format("trial = {}\ntrial_file = {}\n", in.drive_trial->trial,
                     toml_string(fs::absolute(in.drive_trial->source).lexically_normal().string()));
  t += fmt::format("parameters = {}\nmesh_scale = {}\n",
                   toml_string(parameter_text(o.parameters, *in.rig_case)),
                   toml_float(args.mesh_scale));
  t += fmt::format("cases_fnv1a64 = {}\ngeometry_fnv1a64 = {}\ndata_fnv1a64 = {}\n",
                   toml_string(in.cases_hash), toml_string(in.geometry_hash),
                   toml_string(in.data_hash));
  t += fmt::format("started = {}\nfinished = {}\nverdict = {}\nexit_code = {}\n", o.started_at,
                   o.ended_at, toml_string(to_string(s.verdict)), exit_code);
  t += fmt::format("\n[window]\nstart = {}\nend = {}\ngap = {}\ninitial_velocity = {}\n",
                   toml_float(r.window.start), toml_float(r.window.end), toml_float(r.window.gap),
                   toml_float(r.window.initial_velocity));
  t += fmt::format(
      "\n[model]\nelements = {}\nnodes = {}\nimpactor_mass = {}\nartifact_mass = {}\n"
      "artifact_inertia = {}\nsensor_area = {}\nsensor_mesh_area = {}\n",
      r.model.n_elements, r.model.n_nodes, toml_float(r.model.impactor_mass),
      toml_float(r.model.artifact_mass), toml_float(r.model.artifact_inertia),
      toml_float(r.model.sensor_area), toml_float(r.model.sensor_mesh_area));
  t += fmt::format(
      "\n[run]\nsetup_seconds = {}  # {}\nmeshes_made = {}\nmeshes_from_cache = {}\n"
      "steps = {}\ndt_initial = {}\ndt_min = {}\ndt_max = {}\n"
      "wall_seconds = {}\nenergy_balance_error = {}\n",
      toml_float(o.setup_seconds), setup_time_text(o.setup_seconds, o.meshing), o.meshing.misses,
      o.meshing.hits, s.steps, toml_float(s.dt_initial), toml_float(s.dt_min), toml_float(s.dt_max),
      toml_float(s.wall_seconds), toml_float(s.energy_balance_error));
  if (s.verdict == Verdict::unstable)
    t += fmt::format("instability = {}\n", toml_string(instability(s.instability)));
  if (o.objective) t += fmt::format("objective = {}\n", toml_float(*o.objective));
  if (!in.trials.empty()) t += comparison_toml(in, o);
  write_atomic(out / "summary.toml", t);
}

}  // namespace ccm
