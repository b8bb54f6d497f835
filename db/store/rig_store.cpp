#include "db/store/rig_store.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <span>

#include "db/schema/migrations.hpp"
#include "db/sqlite/statement.hpp"
#include "db/sqlite/transaction.hpp"
#include "db/store/provenance.hpp"

namespace ccm::db {
namespace {

constexpr std::array<const char*, 38> kRunColumns = {"case_code",
                                                     "drive",
                                                     "drive_trial",
                                                     "parameters",
                                                     "purpose",
                                                     "status",
                                                     "reason",
                                                     "unstable_time",
                                                     "window_start",
                                                     "window_end",
                                                     "gap",
                                                     "initial_velocity",
                                                     "mesh_scale",
                                                     "n_elements",
                                                     "n_nodes",
                                                     "steps",
                                                     "dt_initial",
                                                     "dt_min",
                                                     "dt_max",
                                                     "wall_seconds",
                                                     "max_energy_error",
                                                     "impactor_mass",
                                                     "artifact_mass",
                                                     "artifact_inertia",
                                                     "sensor_area",
                                                     "sensor_mesh_area",
                                                     "objective",
                                                     "cases_hash",
                                                     "geometry_hash",
                                                     "data_dir",
                                                     "data_hash",
                                                     "ccm_version",
                                                     "git_hash",
                                                     "host",
                                                     "pid",
                                                     "started_at",
                                                     "ended_at",
                                                     "id"};

std::string insert_sql(const char* table, std::span<const char* const> columns) {
  std::string names, values;
  for (size_t i = 0; i < columns.size(); ++i) {
    names += fmt::format("{}{}", i ? ", " : "", columns[i]);
    values += fmt::format("{}?{}", i ? ", " : "", i + 1);
  }
  return fmt::format("INSERT INTO {} ({}) VALUES ({})", table, names, values);
}

// Binds consecutive parameters 1, 2, ... of a statement.
class Binder {
 public:
  explicit Binder(Statement& s) : s_(s) {}
  template <typename T>
  Binder& operator()(const T& value) {
    s_.bind(++i_, value);
    return *this;
  }
  Binder& operator()(const std::optional<int>& value) {
    value ? s_.bind(++i_, *value) : s_.bind_null(++i_);
    return *this;
  }

 private:
  Statement& s_;
  int i_ = 0;
};

long long insert_run_row(Connection& c, const RigRunRow& r, const RunProvenance& p) {
  Statement s(c, insert_sql("rig_runs", std::span(kRunColumns).first(kRunColumns.size() - 1)));
  Binder b(s);
  b(r.case_code)(r.drive)(r.drive_trial)(r.parameters)(r.purpose)(r.status)(r.reason);
  b(r.unstable_time)(r.window_start)(r.window_end)(r.gap)(r.initial_velocity)(r.mesh_scale);
  b(r.n_elements)(r.n_nodes)(r.steps)(r.dt_initial)(r.dt_min)(r.dt_max)(r.wall_seconds);
  b(r.max_energy_error)(r.impactor_mass)(r.artifact_mass)(r.artifact_inertia)(r.sensor_area);
  b(r.sensor_mesh_area)(r.objective)(r.cases_hash)(r.geometry_hash)(r.data_dir)(r.data_hash);
  b(p.ccm_version)(p.git_hash)(p.host)(static_cast<long long>(p.pid))(r.started_at)(r.ended_at);
  s.run();
  return c.last_insert_rowid();
}

void insert_channel(Connection& c, long long run, const char* channel,
                    const rig::ChannelAgainstTrials& a, const std::vector<int>& trials) {
  Statement m(c,
              "INSERT INTO rig_channel_metrics (run_id, channel, trial, n_samples, rmse, nrmse, "
              "peak_measured, peak_simulated, peak_error, peak_time_error) VALUES "
              "(?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10)");
  for (size_t k = 0; k < a.per_trial.size(); ++k) {
    const rig::ChannelComparison& p = a.per_trial[k];
    m.reset();
    m.bind(1, run).bind(2, channel).bind(3, trials.at(k));
    m.bind(4, static_cast<long long>(p.n_samples)).bind(5, p.rmse).bind(6, p.nrmse);
    m.bind(7, p.peak_measured).bind(8, p.peak_simulated).bind(9, p.peak_error);
    m.bind(10, p.peak_time_error);
    m.run();
  }
}

void insert_spread(Connection& c, long long run, const char* channel, const char* metric,
                   const rig::Spread& s, int n) {
  Statement q(
      c,
      "INSERT INTO rig_channel_spread (run_id, channel, metric, n, mean, std_dev, min, max) "
      "VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8)");
  q.bind(1, run).bind(2, channel).bind(3, metric).bind(4, n);
  q.bind(5, s.mean).bind(6, s.std_dev).bind(7, s.min).bind(8, s.max);
  q.run();
}

// Over the scored trials: the simulation's error spread per channel (V_i also inside the
// measured contact windows); over every trial: the measurement's own spread.
void insert_spreads(Connection& c, long long run, const RigRunRecord& r) {
  const int n = static_cast<int>(r.comparison->trials.size());
  const std::array<std::pair<const char*, const rig::ChannelAgainstTrials*>, 3> channels = {
      std::pair{"velocity", &r.comparison->velocity}, std::pair{"angle", &r.comparison->angle},
      std::pair{"pressure", &r.comparison->pressure}};
  for (const auto& [name, a] : channels) {
    insert_spread(c, run, name, "rmse", a->rmse, n);
    insert_spread(c, run, name, "peak_error", a->peak_error, n);
    insert_spread(c, run, name, "peak_time_error", a->peak_time_error, n);
  }
  const rig::ChannelInContact& in_contact = r.comparison->velocity_in_contact;
  const int n_in_contact = static_cast<int>(std::count_if(
      in_contact.per_trial.begin(), in_contact.per_trial.end(), [](const auto& p) { return p; }));
  if (in_contact.rmse)
    insert_spread(c, run, "velocity", "contact_window_rmse", *in_contact.rmse, n_in_contact);
  if (in_contact.nrmse)
    insert_spread(c, run, "velocity", "contact_window_nrmse", *in_contact.nrmse, n_in_contact);
  if (r.comparison->onset_error) {
    insert_spread(c, run, "contact", "onset_error", *r.comparison->onset_error, n);
    insert_spread(c, run, "contact", "duration_error", *r.comparison->duration_error, n);
  }
  if (!r.measured) return;
  const rig::MeasuredSpread& m = *r.measured;
  const std::array<std::pair<const char*, const rig::ChannelSpread*>, 3> measured = {
      std::pair{"velocity", &m.velocity}, std::pair{"angle", &m.angle},
      std::pair{"pressure", &m.pressure}};
  for (const auto& [name, s] : measured) {
    insert_spread(c, run, name, "measured_peak", s->peak, m.n_trials);
    insert_spread(c, run, name, "measured_spread_rms",
                  {s->spread_rms, 0.0, s->spread_rms, s->spread_rms}, m.n_trials);
  }
  if (m.onset) {
    insert_spread(c, run, "contact", "measured_onset", *m.onset, m.n_trials);
    insert_spread(c, run, "contact", "measured_duration", *m.duration, m.n_trials);
  }
}

void insert_contact(Connection& c, long long run, const RigRunRecord& r) {
  Statement q(c,
              "INSERT INTO rig_contact (run_id, trial, measured_onset, measured_duration, "
              "simulated_onset, simulated_duration, onset_error, duration_error) VALUES "
              "(?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8)");
  for (size_t k = 0; k < r.comparison->contact.size(); ++k) {
    const rig::ContactComparison& cc = r.comparison->contact[k];
    q.reset();
    q.bind(1, run).bind(2, r.comparison->trials.at(k));
    q.bind(3, cc.measured ? std::optional(cc.measured->onset) : std::nullopt);
    q.bind(4, cc.measured ? std::optional(cc.measured->duration) : std::nullopt);
    q.bind(5, cc.simulated ? std::optional(cc.simulated->onset) : std::nullopt);
    q.bind(6, cc.simulated ? std::optional(cc.simulated->duration) : std::nullopt);
    q.bind(7, cc.onset_error).bind(8, cc.duration_error);
    q.run();
  }
}

void insert_samples(Connection& c, long long run, const rig::RigChannels& ch) {
  Statement q(
      c, "INSERT INTO rig_channel_samples (run_id, channel, t, value) VALUES (?1, ?2, ?3, ?4)");
  const std::array<std::pair<const char*, const rig::TimeSeries*>, 3> series = {
      std::pair{"velocity", &ch.impactor_velocity_mps}, std::pair{"angle", &ch.artifact_angle_deg},
      std::pair{"pressure", &ch.pressure_kpa}};
  for (const auto& [name, s] : series)
    for (size_t k = 0; k < s->t.size(); ++k) {
      q.reset();
      q.bind(1, run).bind(2, name).bind(3, s->t[k]).bind(4, s->value[k]);
      q.run();
    }
}

bool in_window(double t, const RigRunRow& w) {
  return w.window_end <= w.window_start || (t >= w.window_start && t <= w.window_end);
}

void insert_measured(Connection& c, long long run, const RigRunRecord& r) {
  Statement q(c,
              "INSERT INTO rig_measured_samples (run_id, trial, channel, t, value) VALUES "
              "(?1, ?2, ?3, ?4, ?5)");
  for (size_t j = 0; j < r.measured_channels.size(); ++j) {
    const rig::RigChannels& ch = r.measured_channels[j];
    const std::array<std::pair<const char*, const rig::TimeSeries*>, 3> series = {
        std::pair{"velocity", &ch.impactor_velocity_mps},
        std::pair{"angle", &ch.artifact_angle_deg}, std::pair{"pressure", &ch.pressure_kpa}};
    for (const auto& [name, s] : series)
      for (size_t k = 0; k < s->t.size(); ++k) {
        if (!in_window(s->t[k], r.row)) continue;
        q.reset();
        q.bind(1, run).bind(2, r.trials.at(j)).bind(3, name).bind(4, s->t[k]);
        q.bind(5, s->value[k]);
        q.run();
      }
  }
}

}  // namespace

RigStore::RigStore(const std::filesystem::path& file)
    : file_(file), connection_(std::make_unique<Connection>(file)) {
  migrate(*connection_);
  connection_->exec("PRAGMA journal_mode = WAL", "cannot switch to WAL");
  connection_->exec("PRAGMA foreign_keys = ON", "cannot enable foreign keys");
}

long long RigStore::record_run(const RigRunRecord& r) {
  Transaction transaction(*connection_);
  const long long run = insert_run_row(*connection_, r.row, current_provenance(""));
  if (r.comparison) {
    const std::vector<int>& scored = r.comparison->trials;
    insert_channel(*connection_, run, "velocity", r.comparison->velocity, scored);
    insert_channel(*connection_, run, "angle", r.comparison->angle, scored);
    insert_channel(*connection_, run, "pressure", r.comparison->pressure, scored);
    insert_spreads(*connection_, run, r);
    insert_contact(*connection_, run, r);
  }
  insert_samples(*connection_, run, r.channels);
  insert_measured(*connection_, run, r);
  transaction.commit();
  return run;
}

long long RigStore::record_calibration(const RigCalibrationRecord& r) {
  Transaction transaction(*connection_);
  const RunProvenance p = current_provenance("");
  Statement s(*connection_,
              "INSERT INTO rig_calibrations (case_code, drive, algorithm, objective_name, result, "
              "evaluations, max_evaluations, before_run_id, after_run_id, objective_before, "
              "objective_after, ccm_version, git_hash, host, started_at, ended_at) VALUES "
              "(?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14, ?15, ?16)");
  s.bind(1, r.case_code).bind(2, r.drive).bind(3, r.algorithm).bind(4, r.objective_name);
  s.bind(5, r.result).bind(6, r.evaluations).bind(7, r.max_evaluations);
  s.bind(8, r.before_run_id).bind(9, r.after_run_id).bind(10, r.objective_before);
  s.bind(11, r.objective_after).bind(12, p.ccm_version).bind(13, p.git_hash).bind(14, p.host);
  s.bind(15, r.started_at).bind(16, r.ended_at);
  s.run();
  const long long id = connection_->last_insert_rowid();
  Statement q(*connection_,
              "INSERT INTO rig_calibration_parameters (calibration_id, name, lower, upper, "
              "initial, final, curvature, half_width) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8)");
  for (const RigCalibrationParameter& x : r.parameters) {
    q.reset();
    q.bind(1, id).bind(2, x.name).bind(3, x.lower).bind(4, x.upper).bind(5, x.initial);
    q.bind(6, x.final).bind(7, x.curvature).bind(8, x.half_width);
    q.run();
  }
  Statement w(*connection_,
              "INSERT INTO rig_calibration_predictions (calibration_id, case_code, start_run_id, "
              "calibrated_run_id, objective_start, objective_calibrated) VALUES "
              "(?1, ?2, ?3, ?4, ?5, ?6)");
  for (const RigCalibrationPrediction& x : r.predictions) {
    w.reset();
    w.bind(1, id).bind(2, x.case_code).bind(3, x.start_run_id).bind(4, x.calibrated_run_id);
    w.bind(5, x.objective_start).bind(6, x.objective_calibrated);
    w.run();
  }
  Statement t(*connection_,
              "INSERT INTO rig_calibration_trials (calibration_id, trial, fitted, "
              "objective_before, objective_after) VALUES (?1, ?2, ?3, ?4, ?5)");
  for (const RigCalibrationTrial& x : r.trials) {
    t.reset();
    t.bind(1, id).bind(2, x.trial).bind(3, x.fitted ? 1 : 0).bind(4, x.objective_before);
    t.bind(5, x.objective_after);
    t.run();
  }
  Statement e(*connection_,
              "INSERT INTO rig_calibration_evaluations (calibration_id, evaluation, parameters, "
              "objective, status, wall_seconds) VALUES (?1, ?2, ?3, ?4, ?5, ?6)");
  for (size_t k = 0; k < r.history.size(); ++k) {
    e.reset();
    e.bind(1, id).bind(2, static_cast<long long>(k + 1)).bind(3, r.history[k].parameters);
    e.bind(4, r.history[k].objective).bind(5, r.history[k].status);
    e.bind(6, r.history[k].wall_seconds);
    e.run();
  }
  transaction.commit();
  return id;
}

}  // namespace ccm::db
