#include "rig_models/calibrate/bounded_search.hpp"

#include <fmt/format.h>
#include <nlopt.h>

#include <exception>
#include <limits>
#include <memory>
#include <stdexcept>

namespace ccm::rig {
namespace {

void check(const std::vector<SearchParameter>& parameters, const SearchSettings& settings) {
  if (parameters.empty()) throw std::invalid_argument("calibration: no parameter to tune");
  if (settings.max_evaluations < 1)
    throw std::invalid_argument("calibration: at least one evaluation is needed");
  for (const SearchParameter& p : parameters) {
    if (!(p.lower < p.upper))
      throw std::invalid_argument(
          fmt::format("calibration: {}: the range [{}, {}] is empty", p.name, p.lower, p.upper));
    if (!(p.initial >= p.lower && p.initial <= p.upper))
      throw std::invalid_argument(
          fmt::format("calibration: {}: the starting value {} lies outside [{}, {}]", p.name,
                      p.initial, p.lower, p.upper));
  }
}

// What the C callback needs, and the exception it must not let through NLopt.
struct Context {
  const std::vector<SearchParameter>* parameters;
  const SearchObjective* objective;
  double failure_penalty;
  SearchResult* result;
  std::exception_ptr error;
  nlopt_opt opt;
};

std::vector<double> from_unit(const std::vector<SearchParameter>& p, const double* u) {
  std::vector<double> x(p.size());
  for (size_t i = 0; i < p.size(); ++i) x[i] = p[i].lower + u[i] * (p[i].upper - p[i].lower);
  return x;
}

double evaluate(unsigned n, const double* u, double* /*grad*/, void* data) {
  auto& c = *static_cast<Context*>(data);
  try {
    std::vector<double> x = from_unit(*c.parameters, u);
    (void)n;
    const std::optional<double> f = (*c.objective)(x);
    c.result->history.push_back({x, f});
    if (f && (c.result->best.empty() || *f < c.result->best_objective)) {
      c.result->best = x;
      c.result->best_objective = *f;
    }
    return f ? *f : c.failure_penalty;
  } catch (...) {
    c.error = std::current_exception();
    nlopt_force_stop(c.opt);
    return std::numeric_limits<double>::quiet_NaN();
  }
}

}  // namespace

SearchResult bounded_search(const std::vector<SearchParameter>& parameters,
                            const SearchObjective& objective, const SearchSettings& settings,
                            double failure_penalty) {
  check(parameters, settings);
  const auto n = static_cast<unsigned>(parameters.size());
  SearchResult result;
  // BOBYQA builds a quadratic model from 2n + 1 points, which needs n >= 2.
  const nlopt_algorithm algorithm = n >= 2 ? NLOPT_LN_BOBYQA : NLOPT_LN_COBYLA;
  result.algorithm = n >= 2 ? "LN_BOBYQA" : "LN_COBYLA";
  std::unique_ptr<nlopt_opt_s, decltype(&nlopt_destroy)> opt(nlopt_create(algorithm, n),
                                                             nlopt_destroy);
  if (!opt) throw std::runtime_error("calibration: NLopt could not create its optimiser");
  const std::vector<double> lower(n, 0.0), upper(n, 1.0), step(n, 0.25);
  std::vector<double> u(n);
  for (unsigned i = 0; i < n; ++i)
    u[i] =
        (parameters[i].initial - parameters[i].lower) / (parameters[i].upper - parameters[i].lower);
  Context context{&parameters, &objective, failure_penalty, &result, nullptr, opt.get()};
  // The starting point is evaluated first, as given: BOBYQA would move a start that lies within
  // its first step of a bound before evaluating it, and the caller's "before" must be its start.
  evaluate(n, u.data(), nullptr, &context);
  if (context.error) std::rethrow_exception(context.error);
  if (settings.max_evaluations == 1) {
    if (result.best.empty()) throw std::runtime_error("calibration: the starting point failed");
    result.stop_reason = "MAXEVAL_REACHED";
    return result;
  }
  nlopt_set_lower_bounds(opt.get(), lower.data());
  nlopt_set_upper_bounds(opt.get(), upper.data());
  nlopt_set_initial_step(opt.get(), step.data());
  nlopt_set_maxeval(opt.get(), settings.max_evaluations - 1);
  nlopt_set_xtol_rel(opt.get(), settings.x_tolerance);
  nlopt_set_min_objective(opt.get(), evaluate, &context);
  double f = 0.0;
  const nlopt_result code = nlopt_optimize(opt.get(), u.data(), &f);
  if (context.error) std::rethrow_exception(context.error);
  if (code < 0 && code != NLOPT_ROUNDOFF_LIMITED)
    throw std::runtime_error(
        fmt::format("calibration: NLopt failed: {}", nlopt_result_to_string(code)));
  if (result.best.empty())
    throw std::runtime_error("calibration: every evaluation failed (unstable runs)");
  result.stop_reason = nlopt_result_to_string(code);  // e.g. "MAXEVAL_REACHED"
  return result;
}

}  // namespace ccm::rig
