// The benchtop rig's results in a ccm store (docs/store.md, schema step 3): one row per rig
// simulation with its figures and provenance, its comparison with the measured trials (per
// channel and trial, the spread over the trials, contact onset and duration), the channels it
// was compared on, and the calibrations with their parameters and evaluations. Every record is
// one transaction: a reader sees all of a run or none of it. Read back with
// db/store/rig_reader.hpp.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "db/sqlite/connection.hpp"
#include "rig_models/compare/case_comparison.hpp"
#include "rig_models/compare/measured_spread.hpp"

namespace ccm::db {

struct RigRunRow {
  std::string case_code;
  std::string drive;  // "open-loop" | "physical"
  std::optional<int> drive_trial;
  std::string parameters;       // "name=value;..." of the run's parameters
  std::string purpose = "run";  // "run" | "calibration" (an evaluation of one)
  std::string status;           // "completed" | "unstable"
  std::string reason;
  std::optional<double> unstable_time;
  double window_start = 0.0, window_end = 0.0, gap = 0.0, initial_velocity = 0.0;
  double mesh_scale = 1.0;
  long long n_elements = 0, n_nodes = 0, steps = 0;
  std::optional<double> dt_initial, dt_min, dt_max;
  double wall_seconds = 0.0;
  std::optional<double> max_energy_error;
  double impactor_mass = 0.0, artifact_mass = 0.0, artifact_inertia = 0.0;
  double sensor_area = 0.0, sensor_mesh_area = 0.0;
  std::optional<double> objective;  // the calibration objective of this run, if computed
  std::string cases_hash, geometry_hash, data_dir, data_hash;
  std::string started_at, ended_at;
};

struct RigRunRecord {
  RigRunRow row;
  // Every trial the run was read with, in the order of measured_channels; the comparison names
  // the trials it scored (comparison->trials: all but an open-loop run's driving trial, unless
  // asked for) and only those get per-trial rows.
  std::vector<int> trials;
  std::optional<rig::CaseComparison> comparison;
  std::optional<rig::MeasuredSpread> measured;
  rig::RigChannels channels;  // as compared (sensor model applied)
  // The measured trials the run was compared with, per trial in the order of `trials`, each
  // channel cut to the run window [window_start, window_end] (the whole trial when the window
  // is empty): the report draws them from the store alone.
  std::vector<rig::RigChannels> measured_channels;
};

struct RigCalibrationParameter {
  std::string name;
  double lower = 0.0, upper = 0.0, initial = 0.0, final = 0.0;
  std::optional<double> curvature, half_width;  // the spread; none when not profiled
};

// A case left out of the fit, run with the starting and the calibrated parameters.
struct RigCalibrationPrediction {
  std::string case_code;
  long long start_run_id = 0, calibrated_run_id = 0;
  std::optional<double> objective_start, objective_calibrated;  // none: not compared
};

// A trial the calibrated case is scored on: fitted (the search saw it) or left out of the fit,
// with the objective of the starting and the calibrated run over this trial alone.
struct RigCalibrationTrial {
  int trial = 0;
  bool fitted = true;
  std::optional<double> objective_before, objective_after;  // none: not compared
};

struct RigCalibrationEvaluation {
  std::string parameters;
  std::optional<double> objective;  // none when the run was unstable
  std::string status;
  double wall_seconds = 0.0;
};

struct RigCalibrationRecord {
  std::string case_code, drive, algorithm, objective_name, result;
  int evaluations = 0, max_evaluations = 0;
  long long before_run_id = 0, after_run_id = 0;
  double objective_before = 0.0, objective_after = 0.0;
  std::vector<RigCalibrationParameter> parameters;
  std::vector<RigCalibrationEvaluation> history;
  std::vector<RigCalibrationPrediction> predictions;
  std::vector<RigCalibrationTrial> trials;
  std::string started_at, ended_at;
};

class RigStore {
 public:
  // Opens or creates the store (migrating an older schema; WAL; foreign keys on). Throws
  // StoreError naming the file when it is not a ccm store or was written by a newer ccm.
  explicit RigStore(const std::filesystem::path& file);

  // Each returns the new row id; one transaction each. Provenance (ccm version, git hash, host,
  // process) is this process's.
  long long record_run(const RigRunRecord& run);
  long long record_calibration(const RigCalibrationRecord& calibration);

  Connection& connection() const { return *connection_; }
  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
  std::unique_ptr<Connection> connection_;
};

}  // namespace ccm::db
