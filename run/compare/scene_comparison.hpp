// `ccm compare SCENE --rigid BODY,...` (docs/compare.md): the scene run as written and again with
// the named bodies rigid; the rigid run's errors on the observables against the deformable run
// (the thesis's final-state and cumulative errors, eqs. 2.34-2.39), the measured cost ratio of
// the two step loops, and the answer of the one decision rule (study/recommend/decision_rule.hpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "study/recommend/decision_rule.hpp"

namespace ccm {

struct Scene;

// What one of the two runs left: its verdict, its cost and its history.
struct ComparedRun {
  std::string hash;  // content hash of what was run (compare_hash)
  std::string verdict = "completed";
  std::string reason;  // when unstable
  long steps = 0;
  double step_cpu_seconds = 0.0;  // CPU seconds of the step loop (the cost the ratio compares)
  double wall_seconds = 0.0;
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  bool reused = false;  // read back from an earlier comparison, not run again

  // The index of the history column `name`; none when the run has no such column.
  std::optional<std::size_t> column(const std::string& name) const;
};

struct ObservableErrors {
  std::string column;
  double final_state = 0.0;  // eqs. 2.37-2.39
  double cumulative = 0.0;   // eqs. 2.34-2.36, as a time average (docs/metrics.md)
};

struct ComparisonOutcome {
  std::vector<ObservableErrors> errors;
  // CPU seconds of the deformable run's step loop over the rigid run's (RTR, measured).
  double cost_ratio = 0.0;
  study::Decision decision;
  // Non-empty when the runs cannot be compared (one did not complete, their samples differ):
  // no errors and no decision then.
  std::string unusable;
};

// The observables by default: u_mean, u_max and kinetic_energy of every body that stays
// deformable in `variant` (the scene with the rigid bodies).
std::vector<std::string> default_observables(const Scene& variant);

// Throws std::invalid_argument naming the first observable that is not a column of both runs,
// with the columns it could have been.
void check_observables(const std::vector<std::string>& observables,
                       const std::vector<std::string>& deformable_columns,
                       const std::vector<std::string>& rigid_columns);

ComparisonOutcome compare_runs(const ComparedRun& deformable, const ComparedRun& rigid,
                               const std::vector<std::string>& observables, double max_error);

}  // namespace ccm
