// `ccm rig run CASE [--data DIR --trial N] [--drive open-loop|physical] [--out DIR] [--db FILE]`
// and `ccm rig calibrate CASE --params mu_s,mu_k[,...] --data DIR [...]` (docs/rig-models.md).
#pragma once

#include <string>
#include <vector>

#include "app/rig_inputs.hpp"

namespace ccm {

struct RigCalibrateArgs {
  RigCommonArgs common;
  std::string params;               // comma-separated names (rig_models/sim/run_parameters.hpp)
  std::vector<std::string> bounds;  // name=lower:upper
  int max_evaluations = 12;
  std::string predict;     // comma-separated cases scored with the calibrated parameters, unfitted
  std::string fit_trials;  // comma-separated trial numbers the search fits; the other scored
                           // trials are left out of the fit and scored after it
  bool profile = true;     // the parameters' spread after the fit (2-3 runs each)
  int jobs = 1;            // rig runs at once where the runs do not wait on each other
};

// Exit codes (app/run_command.hpp): 0 completed, 3 unstable (run), 2 bad input (nothing
// written), 1 internal error.
int rig_run_command(const RigCommonArgs& args);
int rig_calibrate_command(const RigCalibrateArgs& args);

}  // namespace ccm
