// `ccm validate SCENE --data FOLDER --fit PATH=LO:HI ...` (docs/bench-test.md, "Fitting"): the
// scene's numbers at the given paths (the path syntax of grids over a scene, docs/grid-file.md)
// fitted to the trials chosen for fitting, by the rig's bounded search (NLopt BOBYQA / COBYLA,
// rig_models/calibrate/bounded_search.hpp) minimising the channels' mean nRMSE against those
// trials' mean curve; each fitted value with its sensitivity half-width and a warning at a bound
// (rig_models/calibrate/parameter_profile.hpp, the rig calibration's); then the scene at the
// fitted values scored on every trial, the left-out ones marked, and written as fitted.toml.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "app/bench_run.hpp"
#include "app/validate_command.hpp"

namespace ccm {

struct FitArgument {
  std::string path;
  double lower = 0.0, upper = 0.0;
};

// "PATH=LO:HI"; throws std::invalid_argument naming the argument.
FitArgument parse_fit_argument(std::string_view text);

// Checks everything before the first run (the paths, the ranges, the trials chosen), fits,
// prints, writes into `out` and records in `store` (when it exists). Returns the exit code.
int validate_fit(const ValidateArgs& args, const BenchData& data, const std::filesystem::path& out,
                 const std::filesystem::path& store);

}  // namespace ccm
