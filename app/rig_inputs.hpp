// Everything `ccm rig run` and `ccm rig calibrate` read, parsed and checked before any
// simulation starts — the case file, the geometry file, every measured trial of the data folder
// (a defective file costs seconds, not a run), the drive, the trial, the parameters, the output
// folder and the store — so that bad input exits 2 with nothing written.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "rig_models/cases/rig_case.hpp"
#include "rig_models/geometry/rig_geometry.hpp"
#include "rig_models/measurement/measured_trial.hpp"
#include "rig_models/sim/run_parameters.hpp"

namespace ccm {

struct RigCommonArgs {
  std::string case_code;
  std::optional<std::filesystem::path> data;  // folder of <CASE>_t<N>.csv
  std::optional<int> trial;                   // default 2 (the thesis simulated the second)
  std::string drive = "open-loop";
  std::optional<double> start, end;  // s, trial time
  double mesh_scale = 1.0;
  std::vector<std::string> set;    // name=value run parameters
  bool score_drive_trial = false;  // open loop: score the run on its driving trial too
  // Default: rig/cases.toml and rig/geometry.toml of the data folder (app/data_paths.hpp).
  std::filesystem::path cases, geometry;
  std::optional<std::filesystem::path> out;
  std::optional<std::filesystem::path> db;
  bool quiet = false;
  // `ccm rig run --fields [--field-interval S]`: every field into --out (docs/fields.md), a
  // frame every field_interval (default kRigFieldEvery output samples).
  bool fields = false;
  std::optional<double> field_interval;  // s
  bool json = false;  // `rig run`: the result as one JSON document instead of the tables
};

inline constexpr int kRigFieldEvery = 10;

inline constexpr int kDefaultTrial = 2;

struct RigInputs {
  std::string cases_text, geometry_text;
  std::string trial_rig_text;  // --data's rig.toml (trial_rig_file.hpp), hashed with the cases
  rig::RigCaseTable cases;
  rig::RigGeometry geometry;
  const rig::RigCase* rig_case = nullptr;
  rig::DriveKind drive = rig::DriveKind::open_loop;
  std::vector<rig::MeasuredTrial> trials;  // of this case, in trial order; empty without data
  const rig::MeasuredTrial* drive_trial = nullptr;
  // The trials the run is scored on: every trial but the open-loop drive's (unless
  // --score-drive-trial), in trial order; the trial left out, if one is.
  std::vector<rig::MeasuredTrial> scored;
  std::optional<int> left_out;
  rig::RunParameters parameters;
  std::string cases_hash, geometry_hash, data_hash;
  std::filesystem::path db;           // --db, else <out>/rig.sqlite, else ./rig.sqlite
  std::vector<std::string> warnings;  // of the measured files read (e.g. an unknown column)
};

// Prints each warning to stderr as "ccm: warning: ...".
void print_warnings(const RigInputs& in);

// Throws rig::RigInputError (a file's defect, with file, line and column or key) or
// std::invalid_argument (a wrong argument, saying what to do).
RigInputs read_rig_inputs(const RigCommonArgs& args);

// "name=value;..." of every parameter that applies to this case.
std::string parameter_text(const rig::RunParameters& p, const rig::RigCase& c);

}  // namespace ccm
