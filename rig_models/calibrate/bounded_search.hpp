// Derivative-free, bounded minimisation of an expensive objective with NLopt (thesis 3.4 tuned
// the friction coefficients by hand; Appendix E's calibration gate asks for it systematically):
// BOBYQA (Powell's bound-constrained quadratic models, NLopt LN_BOBYQA) for two or more
// parameters, COBYLA (LN_COBYLA) for one. Each parameter is mapped to [0, 1] between its bounds,
// so parameters of different units are searched alike; the first step is a quarter of each
// range. Deterministic: the same objective gives the same sequence of evaluations.
//
// The search's first points do not depend on what the objective returns: BOBYQA's initial
// interpolation set (the start and a step either way along each axis, moved off the bounds: 2n + 1
// points) and COBYLA's first simplex vertex (n + 1 points). They are found by a dry run of the
// same NLopt set-up on a constant objective, and evaluated as one batch together with the start,
// which a batch objective may run at once; the search then reads them back. Every point is
// evaluated once: a point NLopt asks for again (its start, when not moved) is read back, not run.
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
  // Evaluations of the opening batch the search never asked for (the start aside): 0 unless
  // NLopt's opening points came to depend on the objective's values.
  int unused_evaluations = 0;
};

// A failed evaluation counts as `failure_penalty` for the search (it steers away from it).
using SearchObjective = std::function<std::optional<double>(const std::vector<double>& x)>;
// Several points at once, in any order or together; the values in the points' order.
using BatchObjective = std::function<std::vector<std::optional<double>>(
    const std::vector<std::vector<double>>& points)>;

// Throws std::invalid_argument for no parameter, an empty or inverted range, an initial value
// outside its range, or max_evaluations < 1; std::runtime_error when NLopt fails (other than by
// reaching a stopping criterion) or every evaluation failed.
// At most settings.max_evaluations evaluations in all (batched or not); the same evaluations in
// the same order whichever form the objective takes.
SearchResult bounded_search(const std::vector<SearchParameter>& parameters,
                            const BatchObjective& objective, const SearchSettings& settings,
                            double failure_penalty = 1e3);
SearchResult bounded_search(const std::vector<SearchParameter>& parameters,
                            const SearchObjective& objective, const SearchSettings& settings,
                            double failure_penalty = 1e3);

// A one-point objective as a batch objective that evaluates its points one after the other.
BatchObjective one_at_a_time(const SearchObjective& objective);

}  // namespace ccm::rig
