// One rig simulation for the rig commands: run_rig with the inputs' case, drive, trial and
// window, the given parameters and a progress line, then compared with every trial.
#pragma once

#include <string>
#include <vector>

#include "app/rig_inputs.hpp"
#include "app/rig_output.hpp"

namespace ccm {

RigRunOutcome run_rig_once(const RigInputs& in, const RigCommonArgs& args,
                           const rig::RunParameters& parameters, const std::string& label);

// One run per parameter set (each labelled), up to `jobs` at once on threads of this process
// (a run steps on one thread; Gmsh, the one shared state, is behind its lock), returned in the
// order given. A run does not depend on what runs beside it: the outcomes are those of
// run_rig_once one after the other. With more than one at once, no progress line is drawn. After a
// run throws no other starts; its exception is rethrown once the running ones have ended.
struct RigRunJob {
  const RigInputs* inputs;
  const RigCommonArgs* args;
  rig::RunParameters parameters;
  std::string label;
};
std::vector<RigRunOutcome> run_rig_batch(const std::vector<RigRunJob>& jobs, int at_once);

}  // namespace ccm
