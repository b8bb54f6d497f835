// Progress of one explicit run on a terminal: one line on stderr, rewritten in place (per cent,
// simulated time, step, dt, wall time, ETA), cleared when the run ends.
#pragma once

#include <string>

#include "engine/solver/explicit_integrator.hpp"

namespace ccm {

class ProgressLine {
 public:
  // `label` leads the line (e.g. "RX025 eval 3/12"); empty: none.
  explicit ProgressLine(std::string label = {}) : label_(std::move(label)) {}
  void operator()(const Progress& p);
  void finish() const;

  // A progress function that writes this line when stderr is a terminal and `quiet` is off;
  // otherwise an empty one (the engine then does not even call it).
  ProgressFn on_terminal(bool quiet);

 private:
  std::string label_;
  bool used_ = false;
};

}  // namespace ccm
