// What the rig commands print, write and store for one rig simulation: the run table (model,
// steps, time step, wall time, energy balance, verdict), the comparison table (per channel, the
// simulation against each trial it is scored on, V_i also inside the measured contact windows,
// and the trials' own spread), the files of --out
// (channels.csv, history.csv, summary.toml, each written whole or not at all) and the store's
// record.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "app/rig_inputs.hpp"
#include "db/store/rig_store.hpp"
#include "engine/mesh/mesh_cache.hpp"
#include "rig_models/compare/case_comparison.hpp"
#include "rig_models/compare/measured_spread.hpp"
#include "rig_models/sim/rig_run.hpp"

namespace ccm {

// A finished run with its comparison (when there are trials).
struct RigRunOutcome {
  rig::RigRunResult result;
  rig::RunParameters parameters;
  std::optional<rig::CaseComparison> comparison;
  std::optional<rig::MeasuredSpread> measured;
  std::optional<double> objective;  // calibration objective (rig_objective.hpp)
  std::string started_at, ended_at;
  double setup_seconds = 0.0;  // from the call to the first step: meshing, masses, the scene
  MeshCacheStats meshing;      // what the mesh cache did meanwhile
};

// Compares the run with the trials it is scored on (in.scored; none without data) and measures
// the spread of every trial.
void compare_with_trials(const RigInputs& in, RigRunOutcome& outcome);

// "trials 1, 3 (trial 2 drives the run and is left out; ...)": which trials score the run.
std::string scored_trials_text(const RigInputs& in);

std::string run_table(const RigInputs& in, const RigRunOutcome& outcome);
std::string comparison_table(const RigInputs& in, const RigRunOutcome& outcome);

db::RigRunRecord store_record(const RigInputs& in, const RigRunOutcome& outcome,
                              const RigCommonArgs& args, std::string_view purpose);

void write_run_files(const std::filesystem::path& out, const RigInputs& in,
                     const RigRunOutcome& outcome, const RigCommonArgs& args, int exit_code);

}  // namespace ccm
