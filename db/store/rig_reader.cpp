#include "db/store/rig_reader.hpp"

#include <string>

#include "db/sqlite/statement.hpp"

namespace ccm::db {
namespace {

std::optional<int> optional_int(const Statement& s, int column) {
  return s.is_null(column) ? std::nullopt : std::optional(static_cast<int>(s.column_int(column)));
}

RigRunRow read_row(Connection& c, long long id) {
  Statement s(c,
              "SELECT case_code, drive, drive_trial, parameters, purpose, status, reason, "
              "unstable_time, window_start, window_end, gap, initial_velocity, mesh_scale, "
              "n_elements, n_nodes, steps, dt_initial, dt_min, dt_max, wall_seconds, "
              "max_energy_error, impactor_mass, artifact_mass, artifact_inertia, sensor_area, "
              "sensor_mesh_area, objective, cases_hash, geometry_hash, data_dir, data_hash, "
              "started_at, ended_at FROM rig_runs WHERE id = ?1");
  s.bind(1, id);
  if (!s.step()) throw StoreError(c.file().string() + ": no rig run " + std::to_string(id));
  RigRunRow r;
  int i = 0;
  const auto text = [&] { return s.column_text(i++); };
  const auto real = [&] { return s.column_double(i++); };
  const auto integer = [&] { return s.column_int(i++); };
  const auto optional = [&] { return s.column_optional_double(i++); };
  r.case_code = text();
  r.drive = text();
  r.drive_trial = optional_int(s, i++);
  r.parameters = text();
  r.purpose = text();
  r.status = text();
  r.reason = text();
  r.unstable_time = optional();
  r.window_start = real();
  r.window_end = real();
  r.gap = real();
  r.initial_velocity = real();
  r.mesh_scale = real();
  r.n_elements = integer();
  r.n_nodes = integer();
  r.steps = integer();
  r.dt_initial = optional();
  r.dt_min = optional();
  r.dt_max = optional();
  r.wall_seconds = real();
  r.max_energy_error = optional();
  r.impactor_mass = real();
  r.artifact_mass = real();
  r.artifact_inertia = real();
  r.sensor_area = real();
  r.sensor_mesh_area = real();
  r.objective = optional();
  r.cases_hash = text();
  r.geometry_hash = text();
  r.data_dir = text();
  r.data_hash = text();
  r.started_at = text();
  r.ended_at = text();
  return r;
}

std::vector<int> read_trials(Connection& c, long long id) {
  Statement s(c,
              "SELECT trial FROM rig_channel_metrics WHERE run_id = ?1 UNION SELECT trial FROM "
              "rig_contact WHERE run_id = ?1 UNION SELECT trial FROM rig_measured_samples WHERE "
              "run_id = ?1 ORDER BY 1");
  s.bind(1, id);
  std::vector<int> out;
  while (s.step()) out.push_back(static_cast<int>(s.column_int(0)));
  return out;
}

std::optional<rig::Spread> read_spread(Connection& c, long long id, const char* channel,
                                       const char* metric) {
  Statement s(c,
              "SELECT mean, std_dev, min, max FROM rig_channel_spread WHERE run_id = ?1 AND "
              "channel = ?2 AND metric = ?3");
  s.bind(1, id).bind(2, channel).bind(3, metric);
  if (!s.step()) return std::nullopt;
  return rig::Spread{s.column_double(0), s.column_double(1), s.column_double(2),
                     s.column_double(3)};
}

rig::ChannelAgainstTrials read_channel(Connection& c, long long id, const char* channel) {
  rig::ChannelAgainstTrials a;
  Statement s(c,
              "SELECT n_samples, rmse, nrmse, peak_measured, peak_simulated, peak_error, "
              "peak_time_error FROM rig_channel_metrics WHERE run_id = ?1 AND channel = ?2 "
              "ORDER BY trial");
  s.bind(1, id).bind(2, channel);
  while (s.step())
    a.per_trial.push_back({static_cast<size_t>(s.column_int(0)), s.column_double(1),
                           s.column_optional_double(2), s.column_double(3), s.column_double(4),
                           s.column_double(5), s.column_double(6)});
  a.rmse = read_spread(c, id, channel, "rmse").value_or(rig::Spread{});
  a.peak_error = read_spread(c, id, channel, "peak_error").value_or(rig::Spread{});
  a.peak_time_error = read_spread(c, id, channel, "peak_time_error").value_or(rig::Spread{});
  return a;
}

std::optional<rig::ContactWindow> window(const Statement& s, int onset, int duration) {
  if (s.is_null(onset) || s.is_null(duration)) return std::nullopt;
  // Whether a contact was still on at the last sample is not stored.
  return rig::ContactWindow{s.column_double(onset), s.column_double(duration), true};
}

// The trials a run was scored on: those with per-trial metrics.
std::vector<int> read_scored_trials(Connection& c, long long id) {
  Statement s(c, "SELECT DISTINCT trial FROM rig_channel_metrics WHERE run_id = ?1 ORDER BY 1");
  s.bind(1, id);
  std::vector<int> out;
  while (s.step()) out.push_back(static_cast<int>(s.column_int(0)));
  return out;
}

std::optional<rig::CaseComparison> read_comparison(Connection& c, long long id) {
  rig::CaseComparison k;
  k.trials = read_scored_trials(c, id);
  k.velocity = read_channel(c, id, "velocity");
  k.angle = read_channel(c, id, "angle");
  k.pressure = read_channel(c, id, "pressure");
  // V_i in the contact windows: only its spread over the trials is stored (per_trial stays empty).
  k.velocity_in_contact.rmse = read_spread(c, id, "velocity", "contact_window_rmse");
  k.velocity_in_contact.nrmse = read_spread(c, id, "velocity", "contact_window_nrmse");
  if (k.velocity.per_trial.empty() && k.angle.per_trial.empty() && k.pressure.per_trial.empty())
    return std::nullopt;
  Statement s(c,
              "SELECT measured_onset, measured_duration, simulated_onset, simulated_duration, "
              "onset_error, duration_error FROM rig_contact WHERE run_id = ?1 ORDER BY trial");
  s.bind(1, id);
  while (s.step())
    k.contact.push_back({window(s, 0, 1), window(s, 2, 3), s.column_optional_double(4),
                         s.column_optional_double(5)});
  k.onset_error = read_spread(c, id, "contact", "onset_error");
  k.duration_error = read_spread(c, id, "contact", "duration_error");
  return k;
}

std::optional<rig::MeasuredSpread> read_measured_spread(Connection& c, long long id, int n) {
  rig::MeasuredSpread m;
  m.n_trials = n;
  bool any = false;
  for (auto [name, ch] : {std::pair{"velocity", &m.velocity}, std::pair{"angle", &m.angle},
                          std::pair{"pressure", &m.pressure}}) {
    const auto peak = read_spread(c, id, name, "measured_peak");
    const auto rms = read_spread(c, id, name, "measured_spread_rms");
    any = any || peak.has_value();
    ch->peak = peak.value_or(rig::Spread{});
    ch->spread_rms = rms ? rms->mean : 0.0;
  }
  m.onset = read_spread(c, id, "contact", "measured_onset");
  m.duration = read_spread(c, id, "contact", "measured_duration");
  return any ? std::optional(m) : std::nullopt;
}

rig::TimeSeries* series_of(rig::RigChannels& ch, const std::string& channel) {
  if (channel == "velocity") return &ch.impactor_velocity_mps;
  if (channel == "angle") return &ch.artifact_angle_deg;
  return &ch.pressure_kpa;
}

rig::RigChannels read_simulated(Connection& c, long long id) {
  rig::RigChannels ch;
  Statement s(c,
              "SELECT channel, t, value FROM rig_channel_samples WHERE run_id = ?1 ORDER BY "
              "channel, t");
  s.bind(1, id);
  while (s.step()) {
    rig::TimeSeries* ts = series_of(ch, s.column_text(0));
    ts->t.push_back(s.column_double(1));
    ts->value.push_back(s.column_double(2));
  }
  return ch;
}

std::vector<rig::RigChannels> read_measured(Connection& c, long long id,
                                            const std::vector<int>& trials) {
  std::vector<rig::RigChannels> out(trials.size());
  Statement s(c,
              "SELECT trial, channel, t, value FROM rig_measured_samples WHERE run_id = ?1 "
              "ORDER BY trial, channel, t");
  s.bind(1, id);
  bool any = false;
  while (s.step()) {
    const int trial = static_cast<int>(s.column_int(0));
    for (size_t j = 0; j < trials.size(); ++j)
      if (trials[j] == trial) {
        rig::TimeSeries* ts = series_of(out[j], s.column_text(1));
        ts->t.push_back(s.column_double(2));
        ts->value.push_back(s.column_double(3));
        any = true;
      }
  }
  if (!any) out.clear();
  return out;
}

}  // namespace

std::vector<long long> latest_rig_run_ids(Connection& c, const char* purpose) {
  Statement s(c,
              "SELECT max(id) FROM rig_runs WHERE purpose = ?1 GROUP BY case_code, drive "
              "ORDER BY case_code, drive");
  s.bind(1, purpose);
  std::vector<long long> out;
  while (s.step()) out.push_back(s.column_int(0));
  return out;
}

StoredRigRun load_rig_run(Connection& c, long long id) {
  StoredRigRun out{id, {}};
  RigRunRecord& r = out.record;
  r.row = read_row(c, id);
  r.trials = read_trials(c, id);
  r.comparison = read_comparison(c, id);
  r.measured = read_measured_spread(c, id, static_cast<int>(r.trials.size()));
  r.channels = read_simulated(c, id);
  r.measured_channels = read_measured(c, id, r.trials);
  return out;
}

std::vector<RigCalibrationRecord> load_rig_calibrations(Connection& c) {
  std::vector<RigCalibrationRecord> out;
  Statement s(c,
              "SELECT id, case_code, drive, algorithm, objective_name, result, evaluations, "
              "max_evaluations, before_run_id, after_run_id, objective_before, "
              "objective_after, started_at, ended_at FROM rig_calibrations ORDER BY id");
  while (s.step()) {
    const long long id = s.column_int(0);
    RigCalibrationRecord k;
    k.case_code = s.column_text(1);
    k.drive = s.column_text(2);
    k.algorithm = s.column_text(3);
    k.objective_name = s.column_text(4);
    k.result = s.column_text(5);
    k.evaluations = static_cast<int>(s.column_int(6));
    k.max_evaluations = static_cast<int>(s.column_int(7));
    k.before_run_id = s.column_int(8);
    k.after_run_id = s.column_int(9);
    k.objective_before = s.column_double(10);
    k.objective_after = s.column_double(11);
    k.started_at = s.column_text(12);
    k.ended_at = s.column_text(13);
    Statement p(c,
                "SELECT name, lower, upper, initial, final, curvature, half_width FROM "
                "rig_calibration_parameters WHERE calibration_id = ?1 ORDER BY name");
    p.bind(1, id);
    while (p.step())
      k.parameters.push_back({p.column_text(0), p.column_double(1), p.column_double(2),
                              p.column_double(3), p.column_double(4), p.column_optional_double(5),
                              p.column_optional_double(6)});
    Statement w(c,
                "SELECT case_code, start_run_id, calibrated_run_id, objective_start, "
                "objective_calibrated FROM rig_calibration_predictions WHERE calibration_id = ?1 "
                "ORDER BY case_code");
    w.bind(1, id);
    while (w.step())
      k.predictions.push_back({w.column_text(0), w.column_int(1), w.column_int(2),
                               w.column_optional_double(3), w.column_optional_double(4)});
    Statement t(c,
                "SELECT trial, fitted, objective_before, objective_after FROM "
                "rig_calibration_trials WHERE calibration_id = ?1 ORDER BY trial");
    t.bind(1, id);
    while (t.step())
      k.trials.push_back({static_cast<int>(t.column_int(0)), t.column_int(1) != 0,
                          t.column_optional_double(2), t.column_optional_double(3)});
    Statement e(c,
                "SELECT parameters, objective, status, wall_seconds FROM "
                "rig_calibration_evaluations WHERE calibration_id = ?1 ORDER BY evaluation");
    e.bind(1, id);
    while (e.step())
      k.history.push_back(
          {e.column_text(0), e.column_optional_double(1), e.column_text(2), e.column_double(3)});
    out.push_back(std::move(k));
  }
  return out;
}

}  // namespace ccm::db
