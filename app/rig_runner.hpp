// One rig simulation for the rig commands: run_rig with the inputs' case, drive, trial and
// window, the given parameters and a progress line, then compared with every trial.
#pragma once

#include <string>

#include "app/rig_inputs.hpp"
#include "app/rig_output.hpp"

namespace ccm {

RigRunOutcome run_rig_once(const RigInputs& in, const RigCommonArgs& args,
                           const rig::RunParameters& parameters, const std::string& label);

}  // namespace ccm
