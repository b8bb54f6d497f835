// `ccm rig run --json`: what the run table, the comparison table and the store's record say,
// as one JSON document (the names those of the store's rig_runs, rig_channel_metrics,
// rig_channel_spread and rig_contact columns, docs/store.md).
#pragma once

#include <nlohmann/json.hpp>

#include "app/rig_inputs.hpp"
#include "app/rig_output.hpp"

namespace ccm {

// `run_id`: the stored rig_runs.id; `exit_code`: the command's.
nlohmann::json rig_run_json(const RigInputs& in, const RigRunOutcome& outcome,
                            const RigCommonArgs& args, long long run_id, int exit_code);

}  // namespace ccm
