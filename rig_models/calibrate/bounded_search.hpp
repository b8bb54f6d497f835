// Derivative-free, bounded minimisation of an expensive objective with NLopt (thesis 3.4 tuned
// the friction coefficients by hand; Appendix E's calibration gate asks for it systematically):
// BOBYQA (Powell's bound-constrained quadratic models, NLopt LN_BOBYQA) for two or more
// parameters, COBYLA (LN_COBYLA) for one. Each parameter is mapped to [0, 1] between its bounds,
// so parameters of different units are searched alike; the first step is a quarter of each
// range. Deterministic: the same objective gives the same sequence of evaluations.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace ccm::rig {

struct SearchParameter {
  std::string name;
  double lower = 0.0, upper = 1.0, initial = 0.0;
};

struct SearchSettings {
  int max_evaluations = 12;
  double x_tolerance = 1e-3;  // relative to each range: stop when a step moves less
};

struct SearchEvaluation {
  std::vector<double> x;
  std::optional<double> objective;  // none: the evaluation failed (an unstable run)
};

struct SearchResult {
  std::vector<double> best;  // the best x evaluated
  double best_objective = 0.0;
  std::vector<SearchEvaluation> history;  // in evaluation order; history[0] is the initial x
  std::string algorithm;                  // "LN_BOBYQA" | "LN_COBYLA"
  std::string stop_reason;                // NLopt's result, e.g. "MAXEVAL_REACHED"
};

// A failed evaluation counts as `failure_penalty` for the search (it steers away from it).
using SearchObjective = std::function<std::optional<double>(const std::vector<double>& x)>;

// Throws std::invalid_argument for no parameter, an empty or inverted range, an initial value
// outside its range, or max_evaluations < 1; std::runtime_error when NLopt fails (other than by
// reaching a stopping criterion) or every evaluation failed.
SearchResult bounded_search(const std::vector<SearchParameter>& parameters,
                            const SearchObjective& objective, const SearchSettings& settings,
                            double failure_penalty = 1e3);

}  // namespace ccm::rig
