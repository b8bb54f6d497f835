// `ccm compare SCENE --rigid BODY[,BODY...]` (docs/compare.md): the scene run as written and with
// the named bodies rigid, the rigid run's errors against the deformable one, the measured cost
// ratio and the decision. Every input is checked (the scene, the bodies, the observables) before
// either run starts; nothing is written on bad input.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "study/recommend/decision_rule.hpp"

namespace ccm {

struct CompareArgs {
  std::filesystem::path scene;
  std::vector<std::string> rigid;    // bodies to make rigid
  std::vector<std::string> observe;  // history columns; empty: the thesis metrics (docs)
  double max_error = study::kDefaultMaxError;
  // The runs (each kept under its content hash, so asking again reuses it) and
  // comparison.json; default: compare-<scene file's stem>.
  std::filesystem::path out;
  // --db: the study whose prediction is shown beside the measured answer, and where the
  // comparison is recorded. Empty: the prediction from the reference store ccm ships when it is
  // installed, else from the main job's store, and the record in the main job's store.
  std::filesystem::path db;
  bool json = false;   // the comparison as JSON on stdout instead of the table
  bool quiet = false;  // no progress line
  int threads = 0;     // as `ccm run --threads`
};

int compare_command(const CompareArgs& args);

}  // namespace ccm
