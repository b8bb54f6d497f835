#include "db/schema/migrations.hpp"

#include <array>
#include <string>

#include "db/sqlite/statement.hpp"
#include "db/sqlite/transaction.hpp"

namespace ccm::db {

namespace {

// Step 1: the run ledger (studies, grid points, one row per simulation with provenance).
constexpr const char* kStep1 = R"sql(
CREATE TABLE studies (
  id INTEGER PRIMARY KEY,
  name TEXT NOT NULL,
  grid_hash TEXT NOT NULL,
  created_at TEXT NOT NULL,
  ccm_version TEXT NOT NULL,
  git_hash TEXT NOT NULL
);
CREATE TABLE grid_points (
  id INTEGER PRIMARY KEY,
  study_id INTEGER NOT NULL REFERENCES studies(id),
  point_index INTEGER NOT NULL,
  content_hash TEXT NOT NULL,
  modulus_ratio REAL NOT NULL,
  length_ratio REAL NOT NULL,
  kinetic_energy REAL NOT NULL,
  other_axes TEXT NOT NULL DEFAULT '',
  UNIQUE (study_id, content_hash)
);
CREATE TABLE runs (
  id INTEGER PRIMARY KEY,
  grid_point_id INTEGER NOT NULL REFERENCES grid_points(id),
  model TEXT NOT NULL CHECK (model IN ('ccm', 'rigid')),
  status TEXT NOT NULL CHECK (status IN ('running', 'completed', 'unstable', 'failed')),
  reason TEXT NOT NULL DEFAULT '',
  unstable_time REAL,
  steps INTEGER,
  wall_seconds REAL,
  initial_stable_dt REAL,
  average_iteration_seconds REAL,
  dt_min REAL,
  dt_max REAL,
  max_energy_error REAL,
  n_elements INTEGER,
  n_nodes INTEGER,
  history_file TEXT,
  history_dataset TEXT,
  scene_hash TEXT NOT NULL DEFAULT '',
  grid_hash TEXT NOT NULL,
  ccm_version TEXT NOT NULL,
  git_hash TEXT NOT NULL,
  host TEXT NOT NULL CHECK (length(host) > 0),
  pid INTEGER NOT NULL,
  ranks INTEGER NOT NULL CHECK (ranks > 0),
  jobs INTEGER NOT NULL CHECK (jobs > 0),
  started_at TEXT NOT NULL,
  ended_at TEXT,
  UNIQUE (grid_point_id, model)
);
)sql";

// Step 2: derived results (metrics per point, surface fits with their terms and points).
constexpr const char* kStep2 = R"sql(
CREATE TABLE metrics (
  grid_point_id INTEGER PRIMARY KEY REFERENCES grid_points(id),
  usable INTEGER NOT NULL CHECK (usable IN (0, 1)),
  excluded_reason TEXT NOT NULL DEFAULT '',
  cumulative_u_mean REAL, cumulative_u_max REAL, cumulative_kinetic_energy REAL,
  final_u_mean REAL, final_u_max REAL, final_kinetic_energy REAL,
  nt_ccm REAL, nt_rigid REAL, tr_ccm REAL, tr_rigid REAL, rtr REAL,
  w_u_mean REAL, w_u_max REAL, w_kinetic_energy REAL,
  t_final REAL,
  computed_at TEXT NOT NULL
);
CREATE TABLE fits (
  id INTEGER PRIMARY KEY,
  study_id INTEGER NOT NULL REFERENCES studies(id),
  metric TEXT NOT NULL,
  kinetic_energy REAL NOT NULL,
  degree_log_er INTEGER NOT NULL,
  degree_rls INTEGER NOT NULL,
  r_squared REAL NOT NULL,
  loo_rmse REAL NOT NULL,
  n_points INTEGER NOT NULL,
  fitted_at TEXT NOT NULL,
  UNIQUE (study_id, metric, kinetic_energy)
);
CREATE TABLE fit_terms (
  fit_id INTEGER NOT NULL REFERENCES fits(id) ON DELETE CASCADE,
  power_log_er INTEGER NOT NULL,
  power_rls INTEGER NOT NULL,
  coefficient REAL NOT NULL,
  PRIMARY KEY (fit_id, power_log_er, power_rls)
);
CREATE TABLE fit_points (
  fit_id INTEGER NOT NULL REFERENCES fits(id) ON DELETE CASCADE,
  grid_point_id INTEGER NOT NULL REFERENCES grid_points(id),
  log10_er REAL NOT NULL,
  rls REAL NOT NULL,
  value REAL NOT NULL,
  PRIMARY KEY (fit_id, grid_point_id)
);
)sql";

// Step 3: the benchtop rig (issue 5): one row per rig simulation with its provenance, its
// comparison with the measured trials (per channel and trial, and the spread over the trials),
// the channels it was compared on, and the calibrations with their parameters and evaluations.
constexpr const char* kStep3 = R"sql(
CREATE TABLE rig_runs (
  id INTEGER PRIMARY KEY,
  case_code TEXT NOT NULL CHECK (length(case_code) = 5),
  drive TEXT NOT NULL CHECK (drive IN ('open-loop', 'physical')),
  drive_trial INTEGER,
  parameters TEXT NOT NULL,
  purpose TEXT NOT NULL CHECK (purpose IN ('run', 'calibration')),
  status TEXT NOT NULL CHECK (status IN ('completed', 'unstable')),
  reason TEXT NOT NULL DEFAULT '',
  unstable_time REAL,
  window_start REAL NOT NULL,
  window_end REAL NOT NULL,
  gap REAL NOT NULL,
  initial_velocity REAL NOT NULL,
  mesh_scale REAL NOT NULL CHECK (mesh_scale > 0),
  n_elements INTEGER NOT NULL,
  n_nodes INTEGER NOT NULL,
  steps INTEGER NOT NULL,
  dt_initial REAL,
  dt_min REAL,
  dt_max REAL,
  wall_seconds REAL NOT NULL,
  max_energy_error REAL,
  impactor_mass REAL NOT NULL,
  artifact_mass REAL NOT NULL,
  artifact_inertia REAL NOT NULL,
  sensor_area REAL NOT NULL,
  sensor_mesh_area REAL NOT NULL,
  objective REAL,
  cases_hash TEXT NOT NULL,
  geometry_hash TEXT NOT NULL,
  data_dir TEXT NOT NULL DEFAULT '',
  data_hash TEXT NOT NULL DEFAULT '',
  ccm_version TEXT NOT NULL,
  git_hash TEXT NOT NULL,
  host TEXT NOT NULL CHECK (length(host) > 0),
  pid INTEGER NOT NULL,
  started_at TEXT NOT NULL,
  ended_at TEXT NOT NULL
);
CREATE TABLE rig_channel_metrics (
  run_id INTEGER NOT NULL REFERENCES rig_runs(id) ON DELETE CASCADE,
  channel TEXT NOT NULL CHECK (channel IN ('velocity', 'angle', 'pressure')),
  trial INTEGER NOT NULL CHECK (trial > 0),
  n_samples INTEGER NOT NULL,
  rmse REAL NOT NULL,
  nrmse REAL,
  peak_measured REAL NOT NULL,
  peak_simulated REAL NOT NULL,
  peak_error REAL NOT NULL,
  peak_time_error REAL NOT NULL,
  PRIMARY KEY (run_id, channel, trial)
);
CREATE TABLE rig_channel_spread (
  run_id INTEGER NOT NULL REFERENCES rig_runs(id) ON DELETE CASCADE,
  channel TEXT NOT NULL CHECK (channel IN ('velocity', 'angle', 'pressure', 'contact')),
  metric TEXT NOT NULL,
  n INTEGER NOT NULL,
  mean REAL NOT NULL,
  std_dev REAL NOT NULL,
  min REAL NOT NULL,
  max REAL NOT NULL,
  PRIMARY KEY (run_id, channel, metric)
);
CREATE TABLE rig_contact (
  run_id INTEGER NOT NULL REFERENCES rig_runs(id) ON DELETE CASCADE,
  trial INTEGER NOT NULL CHECK (trial > 0),
  measured_onset REAL,
  measured_duration REAL,
  simulated_onset REAL,
  simulated_duration REAL,
  onset_error REAL,
  duration_error REAL,
  PRIMARY KEY (run_id, trial)
);
CREATE TABLE rig_channel_samples (
  run_id INTEGER NOT NULL REFERENCES rig_runs(id) ON DELETE CASCADE,
  channel TEXT NOT NULL CHECK (channel IN ('velocity', 'angle', 'pressure')),
  t REAL NOT NULL,
  value REAL NOT NULL,
  PRIMARY KEY (run_id, channel, t)
);
CREATE TABLE rig_measured_samples (
  run_id INTEGER NOT NULL REFERENCES rig_runs(id) ON DELETE CASCADE,
  trial INTEGER NOT NULL CHECK (trial > 0),
  channel TEXT NOT NULL CHECK (channel IN ('velocity', 'angle', 'pressure')),
  t REAL NOT NULL,
  value REAL NOT NULL,
  PRIMARY KEY (run_id, trial, channel, t)
);
CREATE TABLE rig_calibrations (
  id INTEGER PRIMARY KEY,
  case_code TEXT NOT NULL,
  drive TEXT NOT NULL,
  algorithm TEXT NOT NULL,
  objective_name TEXT NOT NULL,
  result TEXT NOT NULL,
  evaluations INTEGER NOT NULL,
  max_evaluations INTEGER NOT NULL,
  before_run_id INTEGER NOT NULL REFERENCES rig_runs(id),
  after_run_id INTEGER NOT NULL REFERENCES rig_runs(id),
  objective_before REAL NOT NULL,
  objective_after REAL NOT NULL,
  ccm_version TEXT NOT NULL,
  git_hash TEXT NOT NULL,
  host TEXT NOT NULL,
  started_at TEXT NOT NULL,
  ended_at TEXT NOT NULL
);
CREATE TABLE rig_calibration_parameters (
  calibration_id INTEGER NOT NULL REFERENCES rig_calibrations(id) ON DELETE CASCADE,
  name TEXT NOT NULL,
  lower REAL NOT NULL,
  upper REAL NOT NULL,
  initial REAL NOT NULL,
  final REAL NOT NULL,
  PRIMARY KEY (calibration_id, name),
  CHECK (lower <= initial AND initial <= upper AND lower <= final AND final <= upper)
);
CREATE TABLE rig_calibration_evaluations (
  calibration_id INTEGER NOT NULL REFERENCES rig_calibrations(id) ON DELETE CASCADE,
  evaluation INTEGER NOT NULL,
  parameters TEXT NOT NULL,
  objective REAL,
  status TEXT NOT NULL,
  wall_seconds REAL NOT NULL,
  PRIMARY KEY (calibration_id, evaluation)
);
)sql";

// Step 4: the measured cost (issue 13). Each run stores what its step loop cost (thread CPU and
// wall seconds), its first and mean step, what set its steps and the smallest contact-limited
// step, and which run it reuses when its scene text repeats another run's. The metrics store
// the measured TR and RTR in tr_ccm, tr_rigid, rtr and the thesis's estimate (t_f AIR / ISTS)
// beside them. Rows written before this step have no measured cost: their runs keep NULL in the
// new columns, and their metrics keep the estimate they stored (moved to the *_thesis_estimate
// columns) and become unusable, with the reason, instead of being given an invented figure.
constexpr const char* kStep4 = R"sql(
ALTER TABLE runs ADD COLUMN step_cpu_seconds REAL;
ALTER TABLE runs ADD COLUMN step_wall_seconds REAL;
ALTER TABLE runs ADD COLUMN dt_first REAL;
ALTER TABLE runs ADD COLUMN dt_mean REAL;
ALTER TABLE runs ADD COLUMN steps_structure INTEGER;
ALTER TABLE runs ADD COLUMN steps_contact INTEGER;
ALTER TABLE runs ADD COLUMN steps_max_dt INTEGER;
ALTER TABLE runs ADD COLUMN steps_landing INTEGER;
ALTER TABLE runs ADD COLUMN dt_contact_min REAL;
ALTER TABLE runs ADD COLUMN reuses_run_id INTEGER;  -- a runs.id (no REFERENCES: droppable)
ALTER TABLE metrics ADD COLUMN tr_ccm_thesis_estimate REAL;
ALTER TABLE metrics ADD COLUMN tr_rigid_thesis_estimate REAL;
ALTER TABLE metrics ADD COLUMN rtr_thesis_estimate REAL;
UPDATE metrics SET
  tr_ccm_thesis_estimate = tr_ccm, tr_rigid_thesis_estimate = tr_rigid, rtr_thesis_estimate = rtr,
  tr_ccm = NULL, tr_rigid = NULL, rtr = NULL,
  w_u_mean = NULL, w_u_max = NULL, w_kinetic_energy = NULL,
  excluded_reason = CASE WHEN usable = 1
    THEN 'measured cost unknown: the runs were stored before store schema 4; run the study again in a new store to measure it'
    ELSE excluded_reason END,
  usable = 0;
DELETE FROM fit_terms WHERE fit_id IN
  (SELECT id FROM fits WHERE metric IN ('rtr', 'w_u_mean', 'w_u_max', 'w_kinetic_energy'));
DELETE FROM fit_points WHERE fit_id IN
  (SELECT id FROM fits WHERE metric IN ('rtr', 'w_u_mean', 'w_u_max', 'w_kinetic_energy'));
DELETE FROM fits WHERE metric IN ('rtr', 'w_u_mean', 'w_u_max', 'w_kinetic_energy');
)sql";

// Step 5 (issue 13): fits per combination of the grid's other axes (`fits.other_axes`, part of
// the unique key: a grid with a damping axis gets one surface per damping level), and the grid
// file's text (`study_grids`), from which every answer states its modelling choices. Fits are
// derived data: the older ones (RTR and w fitted as values, one group per KE) are dropped;
// `ccm study run GRID` on the same grid recomputes them without rerunning anything.
constexpr const char* kStep5 = R"sql(
DROP TABLE fit_points;
DROP TABLE fit_terms;
DROP TABLE fits;
CREATE TABLE fits (
  id INTEGER PRIMARY KEY,
  study_id INTEGER NOT NULL REFERENCES studies(id),
  metric TEXT NOT NULL,
  kinetic_energy REAL NOT NULL,
  other_axes TEXT NOT NULL DEFAULT '',
  degree_log_er INTEGER NOT NULL,
  degree_rls INTEGER NOT NULL,
  r_squared REAL NOT NULL,
  loo_rmse REAL NOT NULL,
  n_points INTEGER NOT NULL,
  fitted_at TEXT NOT NULL,
  UNIQUE (study_id, metric, kinetic_energy, other_axes)
);
CREATE TABLE fit_terms (
  fit_id INTEGER NOT NULL REFERENCES fits(id) ON DELETE CASCADE,
  power_log_er INTEGER NOT NULL,
  power_rls INTEGER NOT NULL,
  coefficient REAL NOT NULL,
  PRIMARY KEY (fit_id, power_log_er, power_rls)
);
CREATE TABLE fit_points (
  fit_id INTEGER NOT NULL REFERENCES fits(id) ON DELETE CASCADE,
  grid_point_id INTEGER NOT NULL REFERENCES grid_points(id),
  log10_er REAL NOT NULL,
  rls REAL NOT NULL,
  value REAL NOT NULL,
  PRIMARY KEY (fit_id, grid_point_id)
);
CREATE TABLE study_grids (
  study_id INTEGER PRIMARY KEY REFERENCES studies(id),
  source TEXT NOT NULL,
  grid_text TEXT NOT NULL,
  saved_at TEXT NOT NULL
);
)sql";

// Step 6: `ccm compare` (docs/compare.md) records each comparison of a scene with some of its
// bodies rigid: what was compared, the measured answer and the study's prediction beside it,
// with the whole comparison.json document and provenance.
constexpr const char* kStep6 = R"sql(
CREATE TABLE comparisons (
  id INTEGER PRIMARY KEY,
  scene TEXT NOT NULL,
  deformable_hash TEXT NOT NULL,
  rigid_hash TEXT NOT NULL,
  rigid_bodies TEXT NOT NULL,
  observables TEXT NOT NULL,
  max_error REAL NOT NULL,
  worst_error REAL,
  cost_ratio REAL,
  answer TEXT,
  unusable TEXT NOT NULL DEFAULT '',
  predicted TEXT,
  agrees INTEGER,
  prediction_note TEXT NOT NULL DEFAULT '',
  document TEXT NOT NULL,
  ccm_version TEXT NOT NULL,
  git_hash TEXT NOT NULL,
  host TEXT NOT NULL,
  recorded_at TEXT NOT NULL
);
)sql";

// Step 7: the designer's metrics of a point (study/metrics/impact_metrics.hpp, IM.1-IM.5): each
// run's peak contact force, deepest indentation of the artifact, contact duration and rebound
// speed, and the rigid run's error in each. NULL where the runs kept no impactor history (stored
// before this step): `ccm study run` recomputes the metrics, not the runs.
constexpr const char* kStep7 = R"sql(
ALTER TABLE metrics ADD COLUMN peak_force_ccm REAL;
ALTER TABLE metrics ADD COLUMN peak_force_rigid REAL;
ALTER TABLE metrics ADD COLUMN indentation_ccm REAL;
ALTER TABLE metrics ADD COLUMN indentation_rigid REAL;
ALTER TABLE metrics ADD COLUMN contact_duration_ccm REAL;
ALTER TABLE metrics ADD COLUMN contact_duration_rigid REAL;
ALTER TABLE metrics ADD COLUMN rebound_speed_ccm REAL;
ALTER TABLE metrics ADD COLUMN rebound_speed_rigid REAL;
ALTER TABLE metrics ADD COLUMN approach_speed REAL;
ALTER TABLE metrics ADD COLUMN error_peak_force REAL;
ALTER TABLE metrics ADD COLUMN error_indentation REAL;
ALTER TABLE metrics ADD COLUMN error_contact_duration REAL;
ALTER TABLE metrics ADD COLUMN error_rebound_speed REAL;
)sql";

// Step 8: how far to trust a rig calibration (app/rig_calibration_checks.hpp): each parameter's
// spread (the objective's curvature along it and the half-width of a 5 % rise; NULL when not
// profiled or a run failed), and the calibrated parameters' score on cases left out of the fit,
// each run with the starting and the calibrated parameters.
constexpr const char* kStep8 = R"sql(
ALTER TABLE rig_calibration_parameters ADD COLUMN curvature REAL;
ALTER TABLE rig_calibration_parameters ADD COLUMN half_width REAL;
CREATE TABLE rig_calibration_predictions (
  calibration_id INTEGER NOT NULL REFERENCES rig_calibrations(id) ON DELETE CASCADE,
  case_code TEXT NOT NULL,
  start_run_id INTEGER NOT NULL REFERENCES rig_runs(id),
  calibrated_run_id INTEGER NOT NULL REFERENCES rig_runs(id),
  objective_start REAL,
  objective_calibrated REAL,
  PRIMARY KEY (calibration_id, case_code)
);
)sql";

// Step 9: `ccm validate` (docs/bench-test.md) records each validation of a scene against a bench
// test: what was compared and fitted, each channel's scores against each trial and the trials'
// mean (nRMSE, peaks, the ISO/TS 18571 sub-scores and grade), each channel's compared curves
// (CSV: time, simulated, mean, low, high) and the whole validation.json.
constexpr const char* kStep9 = R"sql(
CREATE TABLE validations (
  id INTEGER PRIMARY KEY,
  scene TEXT NOT NULL,
  data TEXT NOT NULL,
  fitted TEXT NOT NULL DEFAULT '',
  document TEXT NOT NULL,
  ccm_version TEXT NOT NULL,
  git_hash TEXT NOT NULL,
  host TEXT NOT NULL,
  recorded_at TEXT NOT NULL
);
CREATE TABLE validation_scores (
  validation_id INTEGER NOT NULL REFERENCES validations(id) ON DELETE CASCADE,
  channel TEXT NOT NULL,
  against TEXT NOT NULL,
  left_out INTEGER NOT NULL,
  samples INTEGER NOT NULL,
  nrmse REAL,
  peak_measured REAL NOT NULL,
  peak_simulated REAL NOT NULL,
  peak_time_error REAL NOT NULL,
  corridor REAL NOT NULL,
  phase REAL NOT NULL,
  magnitude REAL NOT NULL,
  slope REAL NOT NULL,
  rating REAL NOT NULL,
  grade TEXT NOT NULL,
  PRIMARY KEY (validation_id, channel, against)
);
CREATE TABLE validation_curves (
  validation_id INTEGER NOT NULL REFERENCES validations(id) ON DELETE CASCADE,
  channel TEXT NOT NULL,
  unit TEXT NOT NULL,
  curves_csv TEXT NOT NULL,
  PRIMARY KEY (validation_id, channel)
);
)sql";

// Step 10: a rig calibration fitted on some of a case's trials and scored on the others
// (`ccm rig calibrate --fit-trials`): per scored trial, whether the fit saw it, and the objective
// of the starting and of the calibrated run over that trial alone (NULL: not compared).
constexpr const char* kStep10 = R"sql(
CREATE TABLE rig_calibration_trials (
  calibration_id INTEGER NOT NULL REFERENCES rig_calibrations(id) ON DELETE CASCADE,
  trial INTEGER NOT NULL,
  fitted INTEGER NOT NULL CHECK (fitted IN (0, 1)),
  objective_before REAL,
  objective_after REAL,
  PRIMARY KEY (calibration_id, trial)
);
)sql";

constexpr std::array<const char*, 10> kSteps = {kStep1, kStep2, kStep3, kStep4, kStep5,
                                                kStep6, kStep7, kStep8, kStep9, kStep10};

int pragma_int(Connection& connection, const char* pragma) {
  Statement query(connection, std::string("PRAGMA ") + pragma);
  return query.step() ? static_cast<int>(query.column_int(0)) : 0;
}

int count_tables(Connection& connection) {
  Statement query(connection, "SELECT count(*) FROM sqlite_schema WHERE type = 'table'");
  query.step();
  return static_cast<int>(query.column_int(0));
}

void refuse_foreign_or_newer(Connection& connection, int version, int application_id) {
  const std::string file = connection.file().string();
  if (application_id != 0 && application_id != kApplicationId)
    throw StoreError(file + ": not a ccm study store (application_id " +
                     std::to_string(application_id) + ", expected " +
                     std::to_string(kApplicationId) + "); refusing to touch it");
  if (application_id == 0 && count_tables(connection) > 0)
    throw StoreError(file +
                     ": an SQLite file with tables but no ccm application_id is not a "
                     "ccm study store; refusing to touch it");
  if (version < 0)  // user_version is a signed 32-bit header field: damage, not a ccm version
    throw StoreError(file + ": schema version " + std::to_string(version) +
                     " is negative: the file's header is damaged (not a ccm study store)");
  if (version > latest_schema_version())
    throw StoreError(file + ": schema version " + std::to_string(version) +
                     " was written by a newer ccm (this build knows up to " +
                     std::to_string(latest_schema_version()) + "); upgrade ccm to open it");
}

}  // namespace

int latest_schema_version() { return static_cast<int>(kSteps.size()); }

int schema_version(Connection& connection) { return pragma_int(connection, "user_version"); }

namespace {

struct StoreHeader {
  int version = 0;
  int application_id = 0;
};

// Reading the header also makes SQLite reject a file that is not a database at all.
StoreHeader read_header(Connection& connection) {
  try {
    return {schema_version(connection), pragma_int(connection, "application_id")};
  } catch (const StoreError& e) {
    throw StoreError(std::string(e.what()) + " (not a ccm study store)");
  }
}

}  // namespace

int check_existing_store(Connection& connection) {
  const StoreHeader header = read_header(connection);
  refuse_foreign_or_newer(connection, header.version, header.application_id);
  if (header.application_id != kApplicationId)
    throw StoreError(connection.file().string() +
                     ": not a ccm study store (an empty file or an SQLite file without the ccm "
                     "application_id); refusing to touch it");
  return header.version;
}

void migrate(Connection& connection, int target_version) {
  const auto [version, application_id] = read_header(connection);
  refuse_foreign_or_newer(connection, version, application_id);
  for (int step = version; step < target_version; ++step) {
    Transaction transaction(connection);
    // Re-read under the write lock: another process may have migrated meanwhile.
    if (schema_version(connection) > step) continue;
    connection.exec(kSteps[static_cast<std::size_t>(step)],
                    "schema migration step " + std::to_string(step + 1));
    connection.exec("PRAGMA application_id = " + std::to_string(kApplicationId));
    connection.exec("PRAGMA user_version = " + std::to_string(step + 1));
    transaction.commit();
  }
}

}  // namespace ccm::db
