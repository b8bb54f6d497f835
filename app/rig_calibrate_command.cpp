// `ccm rig calibrate`: read and check every input, then a derivative-free bounded search
// (rig_models/calibrate/bounded_search.hpp) of the named parameters against the measured trials
// the run is scored on (all but the open-loop drive's, unless --score-drive-trial); the starting
// and the best run are stored with their comparisons, the calibration with its parameters and every
// evaluation, and before/after are printed.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

#include "app/rig_calibration_checks.hpp"
#include "app/rig_command_errors.hpp"
#include "app/rig_commands.hpp"
#include "app/rig_runner.hpp"
#include "app/run_command.hpp"
#include "records/provenance/timestamp.hpp"
#include "rig_models/calibrate/bounded_search.hpp"
#include "rig_models/calibrate/rig_objective.hpp"
#include "rig_models/core/rig_error.hpp"

namespace ccm {
namespace {

struct Range {
  double lower, upper;
};

// Default search ranges: a free pin's coefficients over [0, 1], a fixed case's frictional pin
// (thesis 3.4.1 used mu_s = 50) over [0, 100]; the track's as the case file's assumptions
// allow; K_s within a factor two of the characterised 1895 N/m.
Range default_range(std::string_view name, const RigInputs& in) {
  const bool fixed = in.rig_case->artifact == rig::ArtifactKind::fixed;
  if (name == "mu_s" || name == "mu_k") return fixed ? Range{0.0, 100.0} : Range{0.0, 1.0};
  if (name == "track_friction" || name == "track_static_friction") return {0.0, 0.2};
  if (name == "track_damping") return {0.0, 5.0};
  // The clamp: a decade either side of cases.toml's estimate, 0 to 20 % of critical damping.
  if (name == "clamp_stiffness")
    return {0.1 * in.cases.rig.clamp_stiffness.value, 10.0 * in.cases.rig.clamp_stiffness.value};
  if (name == "clamp_damping") return {0.0, 4.0 * in.cases.rig.clamp_damping.value};
  // The mat: a stiffness from a soft foam to a stiff rubber; lambda for e from 1 down to ~0.
  if (name == "mat_stiffness") return {1e3, 1e6};
  if (name == "mat_damping") return {0.0, 10.0};
  const double K = in.cases.rig.spring_stiffness.value;
  return {0.5 * K, 2.0 * K};
}

double parse_number(std::string_view text, const std::string& what) {
  double v = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v))
    throw std::invalid_argument(fmt::format("{}: '{}' is not a number", what, text));
  return v;
}

std::map<std::string, Range> parse_bounds(const std::vector<std::string>& bounds) {
  std::map<std::string, Range> out;
  for (const std::string& b : bounds) {
    const size_t eq = b.find('='), colon = b.find(':');
    if (eq == std::string::npos || colon == std::string::npos || colon < eq)
      throw std::invalid_argument(fmt::format("--bounds {}: expected name=lower:upper", b));
    out[b.substr(0, eq)] = {parse_number(b.substr(eq + 1, colon - eq - 1), "--bounds " + b),
                            parse_number(b.substr(colon + 1), "--bounds " + b)};
  }
  return out;
}

std::vector<rig::SearchParameter> search_parameters(const RigCalibrateArgs& args,
                                                    const RigInputs& in) {
  std::map<std::string, Range> bounds = parse_bounds(args.bounds);
  std::vector<rig::SearchParameter> out;
  std::stringstream names(args.params);
  for (std::string name; std::getline(names, name, ',');) {
    if (const std::string p = rig::parameter_problem(name, *in.rig_case); !p.empty())
      throw std::invalid_argument(fmt::format("--params: {}", p));
    for (const auto& q : out)
      if (q.name == name) throw std::invalid_argument(fmt::format("--params: {} twice", name));
    const Range r = bounds.count(name) ? bounds.at(name) : default_range(name, in);
    bounds.erase(name);
    const double initial = rig::get_parameter(in.parameters, name);
    if (!(r.lower >= 0.0 && r.lower < r.upper))
      throw std::invalid_argument(
          fmt::format("--bounds {}: need 0 <= lower < upper (got {}:{})", name, r.lower, r.upper));
    if (!(initial >= r.lower && initial <= r.upper))
      throw std::invalid_argument(fmt::format(
          "{}: the starting value {} lies outside [{}, {}]; widen it with --bounds {}=lo:hi", name,
          initial, r.lower, r.upper, name));
    out.push_back({name, r.lower, r.upper, initial});
  }
  if (out.empty()) throw std::invalid_argument("--params: name at least one parameter");
  if (!bounds.empty())
    throw std::invalid_argument(
        fmt::format("--bounds {}: not among --params", bounds.begin()->first));
  return out;
}

std::string values_text(const std::vector<rig::SearchParameter>& s, const std::vector<double>& x) {
  std::string t;
  for (size_t i = 0; i < s.size(); ++i)
    t += fmt::format("{}{}={:.6g}", i ? ";" : "", s[i].name, x[i]);
  return t;
}

int calibrate(const RigCalibrateArgs& args) {
  const RigCommonArgs& common = args.common;
  const RigInputs in = read_rig_inputs(common);
  print_warnings(in);
  if (in.trials.empty())
    throw std::invalid_argument("calibration fits the measured trials: give --data DIR");
  if (in.scored.empty())
    throw std::invalid_argument(fmt::format(
        "--data {}: {} has no trial but trial {}, which drives the run: a calibration on it "
        "would fit the run's own input; add trials, or --score-drive-trial to fit it anyway",
        common.data->string(), in.rig_case->code, *in.left_out));
  if (args.max_evaluations < 1 || args.max_evaluations > 500)
    throw std::invalid_argument("--max-evals must lie in [1, 500]");
  if (args.jobs < 1 || args.jobs > 64)
    throw std::invalid_argument(fmt::format("--jobs must lie in [1, 64] (got {})", args.jobs));
  const std::vector<rig::SearchParameter> params = search_parameters(args, in);
  const std::vector<int> fit = read_fit_trials(args, in);
  std::vector<PredictionCase> predicted = read_prediction_cases(args, in, params);
  if (in.db.has_parent_path()) std::filesystem::create_directories(in.db.parent_path());
  db::RigStore store(in.db);
  const std::string started = utc_timestamp_now();
  std::vector<RigRunOutcome> first_and_best;  // [0] the start, [1] the best so far
  std::vector<db::RigCalibrationEvaluation> history;
  int evaluation = 0;
  // One evaluation's bookkeeping: its history row, its line, the start and the best so far.
  auto book_evaluation = [&](const std::vector<double>& x,
                             RigRunOutcome o) -> std::optional<double> {
    ++evaluation;
    // The run keeps its objective over every scored trial; the search reads the fitted trials'.
    const std::optional<double> fitted = fitted_objective(o, fit);
    const bool ok = o.result.summary.verdict == Verdict::completed && fitted;
    history.push_back({values_text(params, x), ok ? fitted : std::nullopt,
                       std::string(to_string(o.result.summary.verdict)),
                       o.result.summary.wall_seconds});
    if (!common.quiet)
      fmt::print("  eval {:>3}  {:<40} objective {}\n", evaluation, values_text(params, x),
                 ok ? fmt::format("{:.5f}", *fitted) : "- (" + history.back().status + ")");
    if (first_and_best.empty()) first_and_best.push_back(o);
    if (ok && (first_and_best.size() < 2 || *fitted < *fitted_objective(first_and_best[1], fit))) {
      if (first_and_best.size() < 2)
        first_and_best.push_back(o);
      else
        first_and_best[1] = std::move(o);
    }
    if (!ok) return std::nullopt;
    return *history.back().objective;
  };
  // The search's points, a batch at a time (its opening points go out together: up to --jobs
  // runs at once); the bookkeeping in the order of the points.
  const rig::BatchObjective objective = [&](const std::vector<std::vector<double>>& points) {
    const std::vector<RigRunJob> jobs = runs_at(in, common, params, points, [&](size_t k) {
      return fmt::format("{} eval {}/{}", in.rig_case->code, evaluation + static_cast<int>(k) + 1,
                         args.max_evaluations);
    });
    if (!common.quiet && points.size() > 1 && args.jobs > 1)
      fmt::print("  evals {}-{}: {} runs, {} at once\n", evaluation + 1,
                 evaluation + static_cast<int>(points.size()), points.size(),
                 std::min<size_t>(points.size(), static_cast<size_t>(args.jobs)));
    std::vector<RigRunOutcome> outcomes = run_rig_batch(jobs, args.jobs);
    std::vector<std::optional<double>> values;
    for (size_t k = 0; k < outcomes.size(); ++k)
      values.push_back(book_evaluation(points[k], std::move(outcomes[k])));
    return values;
  };
  if (!common.quiet)
    fmt::print(
        "ccm rig calibrate {} ({} drive): {} of {}{}\n", in.rig_case->code, name_of(in.drive),
        rig::kObjectiveName, scored_trials_text(in),
        fit.empty() ? std::string() : fmt::format(", fitted on trial(s) {}", fmt::join(fit, ", ")));
  const rig::SearchResult result =
      rig::bounded_search(params, objective, {args.max_evaluations, 1e-3});
  const RigRunOutcome& before = first_and_best[0];
  const RigRunOutcome& after = first_and_best.size() > 1 ? first_and_best[1] : before;
  const std::optional<double> fitted_before = fitted_objective(before, fit),
                              fitted_after = fitted_objective(after, fit);
  if (!fitted_before)
    throw std::runtime_error("calibration: the starting run could not be compared (unstable)");
  const long long before_id = store.record_run(store_record(in, before, common, "calibration"));
  const long long after_id = store.record_run(store_record(in, after, common, "calibration"));
  db::RigCalibrationRecord rec;
  rec.case_code = in.rig_case->code;
  rec.drive = std::string(name_of(in.drive));
  rec.algorithm = result.algorithm;
  rec.objective_name = std::string(rig::kObjectiveName);
  rec.result = result.stop_reason;
  rec.evaluations = static_cast<int>(result.history.size());
  rec.max_evaluations = args.max_evaluations;
  rec.before_run_id = before_id;
  rec.after_run_id = after_id;
  rec.objective_before = *fitted_before;  // what the search minimised
  rec.objective_after = *fitted_after;
  for (size_t i = 0; i < params.size(); ++i)
    rec.parameters.push_back({params[i].name, params[i].lower, params[i].upper, params[i].initial,
                              result.best[i], std::nullopt, std::nullopt});
  rec.history = history;
  const std::vector<rig::ParameterSpread> spread =
      args.profile ? profile_calibration(in, common, params, fit, result.best,
                                         result.best_objective, args.jobs)
                   : std::vector<rig::ParameterSpread>{};
  for (size_t i = 0; i < spread.size(); ++i) {
    rec.parameters[i].curvature = spread[i].curvature;
    rec.parameters[i].half_width = spread[i].half_width;
  }
  const std::vector<Prediction> predictions =
      run_predictions(predicted, params, result.best, args.jobs);
  for (const Prediction& p : predictions) {
    const PredictionCase& c = *p.predicted;
    rec.predictions.push_back(
        {c.inputs.rig_case->code,
         store.record_run(store_record(c.inputs, p.start, c.args, "calibration")),
         store.record_run(store_record(c.inputs, p.calibrated, c.args, "calibration")),
         p.start.objective, p.calibrated.objective});
  }
  rec.trials = trial_scores(in, fit, before, after);
  rec.started_at = started;
  rec.ended_at = utc_timestamp_now();
  const long long id = store.record_calibration(rec);
  if (!common.quiet) {
    fmt::print("\n{} after {} evaluations ({}; {})\n", result.algorithm, rec.evaluations,
               result.stop_reason, rig::kObjectiveName);
    fmt::print("  {:<18} {:>10} {:>10} {:>12} {:>12}\n", "parameter", "lower", "upper", "before",
               "after");
    for (const auto& p : rec.parameters)
      fmt::print("  {:<18} {:>10.4g} {:>10.4g} {:>12.6g} {:>12.6g}\n", p.name, p.lower, p.upper,
                 p.initial, p.final);
    fmt::print("  {:<18} {:>10} {:>10} {:>12.5f} {:>12.5f}\n", "objective", "", "",
               rec.objective_before, rec.objective_after);
    fmt::print("\nBefore (rig_runs.id {}):\n{}{}", before_id, run_table(in, before),
               comparison_table(in, before));
    fmt::print("\nAfter (rig_runs.id {}):\n{}{}", after_id, run_table(in, after),
               comparison_table(in, after));
    fmt::print("\nstored in {} (rig_calibrations.id {})\n", in.db.string(), id);
    print_trial_scores(rec.trials, before, after);
    print_spread(spread);
    print_predictions(predictions);
  }
  return exit_code::completed;
}

}  // namespace

int rig_calibrate_command(const RigCalibrateArgs& args) {
  return run_rig_reporting_errors([&] { return calibrate(args); });
}

}  // namespace ccm
