// `ccm validate SCENE --data FOLDER` (docs/bench-test.md): the scene run once and compared with
// the bench test whose mapping file (bench.toml) and trial CSVs are in FOLDER: every channel
// against every trial and against the trials' mean, by nRMSE, peak and time-of-peak errors and
// the ISO/TS 18571 rating. The mapping, the trials and the scene's observables are all checked
// before the run starts; nothing is written on bad input.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace ccm {

struct ValidateArgs {
  std::filesystem::path scene;
  std::filesystem::path data;  // the folder of bench.toml and the trials
  // history.csv, validation.json and one <channel>.csv of the curves compared;
  // default: validate-<scene file's stem>.
  std::filesystem::path out;
  // --db: the store the validation is recorded in (docs/store.md, `ccm report` shows it); empty:
  // the main job's store when it exists.
  std::filesystem::path db;
  bool json = false;   // the scores as JSON on stdout instead of the tables
  bool quiet = false;  // no progress line
  int threads = 0;     // as `ccm run --threads`
  // --fit PATH=LO:HI: scene paths (docs/grid-file.md's path syntax) fitted to the trials
  // (app/validate_fit.hpp); --fit-trials: the trials fitted to (1-based, in file-name order;
  // default all but the last), the others left out and scored with the fitted values.
  std::vector<std::string> fit;
  std::vector<int> fit_trials;
  // --cross-validate: each trial left out in turn (a fit on the others, scored on it), then the
  // fit on every trial.
  bool cross_validate = false;
  int evaluations = 16;  // the search's budget of runs (the profile adds 2-3 per parameter)
};

int validate_command(const ValidateArgs& args);

}  // namespace ccm
