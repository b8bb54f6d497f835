#include "rig_models/calibrate/bounded_search.hpp"

#include <fmt/format.h>
#include <nlopt.h>

#include <algorithm>
#include <exception>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>

namespace ccm::rig {
namespace {

using Point = std::vector<double>;  // a point of the search in unit coordinates

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
  const BatchObjective* objective;
  double failure_penalty;
  SearchResult* result;
  std::map<Point, std::optional<double>> known;  // every evaluated point, by unit coordinates
  std::set<Point> asked;                         // the points NLopt asked for
  std::exception_ptr error;
  nlopt_opt opt;
};

std::vector<double> from_unit(const std::vector<SearchParameter>& p, const Point& u) {
  std::vector<double> x(p.size());
  for (size_t i = 0; i < p.size(); ++i) x[i] = p[i].lower + u[i] * (p[i].upper - p[i].lower);
  return x;
}

// Evaluates, as one batch in the given order, the points not evaluated yet.
void evaluate_new(Context& c, const std::vector<Point>& points) {
  std::vector<Point> fresh;
  for (const Point& u : points)
    if (!c.known.count(u) && std::find(fresh.begin(), fresh.end(), u) == fresh.end())
      fresh.push_back(u);
  if (fresh.empty()) return;
  std::vector<std::vector<double>> xs;
  for (const Point& u : fresh) xs.push_back(from_unit(*c.parameters, u));
  const std::vector<std::optional<double>> f = (*c.objective)(xs);
  if (f.size() != xs.size())
    throw std::logic_error("calibration: the objective returned another number of values");
  for (size_t k = 0; k < fresh.size(); ++k) {
    c.known[fresh[k]] = f[k];
    c.result->history.push_back({xs[k], f[k]});
    if (f[k] && (c.result->best.empty() || *f[k] < c.result->best_objective)) {
      c.result->best = xs[k];
      c.result->best_objective = *f[k];
    }
  }
}

double ask(unsigned n, const double* u, double* /*grad*/, void* data) {
  auto& c = *static_cast<Context*>(data);
  try {
    const Point p(u, u + n);
    c.asked.insert(p);
    evaluate_new(c, {p});
    const std::optional<double>& f = c.known.at(p);
    return f ? *f : c.failure_penalty;
  } catch (...) {
    c.error = std::current_exception();
    nlopt_force_stop(c.opt);
    return std::numeric_limits<double>::quiet_NaN();
  }
}

using Optimiser = std::unique_ptr<nlopt_opt_s, decltype(&nlopt_destroy)>;

// The search's NLopt set-up: the unit box, a first step of a quarter of it, the x tolerance.
Optimiser make_optimiser(nlopt_algorithm algorithm, unsigned n, double x_tolerance, int max_eval) {
  Optimiser opt(nlopt_create(algorithm, n), nlopt_destroy);
  if (!opt) throw std::runtime_error("calibration: NLopt could not create its optimiser");
  const std::vector<double> lower(n, 0.0), upper(n, 1.0), step(n, 0.25);
  nlopt_set_lower_bounds(opt.get(), lower.data());
  nlopt_set_upper_bounds(opt.get(), upper.data());
  nlopt_set_initial_step(opt.get(), step.data());
  nlopt_set_maxeval(opt.get(), max_eval);
  nlopt_set_xtol_rel(opt.get(), x_tolerance);
  return opt;
}

// The first `count` points the search asks for from `start`: a dry run of the same set-up on a
// constant objective. BOBYQA's initial interpolation set and COBYLA's first vertex do not depend
// on the values (header), so the real search asks for the same points.
std::vector<Point> opening_points(nlopt_algorithm algorithm, const Point& start, double x_tolerance,
                                  int count) {
  if (count < 1) return {};
  const auto n = static_cast<unsigned>(start.size());
  Optimiser opt = make_optimiser(algorithm, n, x_tolerance, count);
  std::vector<Point> asked;
  nlopt_set_min_objective(
      opt.get(),
      [](unsigned m, const double* u, double*, void* data) {
        static_cast<std::vector<Point>*>(data)->emplace_back(u, u + m);
        return 0.0;
      },
      &asked);
  Point u = start;
  double f = 0.0;
  nlopt_optimize(opt.get(), u.data(), &f);
  return asked;
}

}  // namespace

BatchObjective one_at_a_time(const SearchObjective& objective) {
  return [objective](const std::vector<std::vector<double>>& points) {
    std::vector<std::optional<double>> out;
    for (const std::vector<double>& x : points) out.push_back(objective(x));
    return out;
  };
}

SearchResult bounded_search(const std::vector<SearchParameter>& parameters,
                            const SearchObjective& objective, const SearchSettings& settings,
                            double failure_penalty) {
  return bounded_search(parameters, one_at_a_time(objective), settings, failure_penalty);
}

SearchResult bounded_search(const std::vector<SearchParameter>& parameters,
                            const BatchObjective& objective, const SearchSettings& settings,
                            double failure_penalty) {
  check(parameters, settings);
  const auto n = static_cast<unsigned>(parameters.size());
  SearchResult result;
  // BOBYQA builds a quadratic model from 2n + 1 points, which needs n >= 2.
  const nlopt_algorithm algorithm = n >= 2 ? NLOPT_LN_BOBYQA : NLOPT_LN_COBYLA;
  result.algorithm = n >= 2 ? "LN_BOBYQA" : "LN_COBYLA";
  const int opening_size = n >= 2 ? static_cast<int>(2 * n + 1) : static_cast<int>(n + 1);
  Point u(n);
  for (unsigned i = 0; i < n; ++i)
    u[i] =
        (parameters[i].initial - parameters[i].lower) / (parameters[i].upper - parameters[i].lower);
  const std::vector<Point> opening = opening_points(
      algorithm, u, settings.x_tolerance, std::min(opening_size, settings.max_evaluations - 1));
  Context context{&parameters, &objective, failure_penalty, &result, {}, {}, nullptr, nullptr};
  // The starting point is evaluated first, as given: BOBYQA would move a start that lies within
  // its first step of a bound before evaluating it, and the caller's "before" must be its start.
  // With it, the points the search will open with, as one batch.
  std::vector<Point> first{u};
  first.insert(first.end(), opening.begin(), opening.end());
  evaluate_new(context, first);
  const int budget_left = settings.max_evaluations - static_cast<int>(result.history.size());
  if (settings.max_evaluations == 1) {
    if (result.best.empty()) throw std::runtime_error("calibration: the starting point failed");
    result.stop_reason = "MAXEVAL_REACHED";
    return result;
  }
  // NLopt counts the opening points it reads back as evaluations: give it those and the rest.
  Optimiser opt = make_optimiser(algorithm, n, settings.x_tolerance,
                                 static_cast<int>(opening.size()) + budget_left);
  context.opt = opt.get();
  nlopt_set_min_objective(opt.get(), ask, &context);
  double f = 0.0;
  const nlopt_result code = nlopt_optimize(opt.get(), u.data(), &f);
  if (context.error) std::rethrow_exception(context.error);
  if (code < 0 && code != NLOPT_ROUNDOFF_LIMITED)
    throw std::runtime_error(
        fmt::format("calibration: NLopt failed: {}", nlopt_result_to_string(code)));
  if (result.best.empty())
    throw std::runtime_error("calibration: every evaluation failed (unstable runs)");
  result.stop_reason = nlopt_result_to_string(code);  // e.g. "MAXEVAL_REACHED"
  for (const Point& p : opening)
    if (!context.asked.count(p) && p != first.front()) ++result.unused_evaluations;
  return result;
}

}  // namespace ccm::rig
