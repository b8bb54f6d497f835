#include "app/rig_calibration_checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <sstream>
#include <stdexcept>

#include "app/rig_runner.hpp"
#include "rig_models/calibrate/parameter_profile.hpp"
#include "rig_models/calibrate/rig_objective.hpp"
#include "rig_models/sim/run_window.hpp"

namespace ccm {
namespace {

std::vector<std::string> split_codes(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream in(list);
  for (std::string code; std::getline(in, code, ',');)
    if (!code.empty()) out.push_back(code);
  return out;
}

std::string objective_text(const RigRunOutcome& o) {
  return o.objective ? fmt::format("{:.5f}", *o.objective) : std::string("- (not compared)");
}

std::string check_prediction(const std::string& code, const RigInputs& fitted,
                             const RigInputs& predicted,
                             const std::vector<rig::SearchParameter>& params) {
  if (code == fitted.rig_case->code) return "it is the fitted case";
  if (code.substr(0, 2) != fitted.rig_case->code.substr(0, 2))
    return fmt::format(
        "not {}'s configuration ({} impactor, {} artifact): one parameter set per configuration",
        fitted.rig_case->code, rig::name_of(fitted.rig_case->impactor),
        rig::name_of(fitted.rig_case->artifact));
  for (const rig::SearchParameter& p : params)
    if (const std::string problem = rig::parameter_problem(p.name, *predicted.rig_case);
        !problem.empty())
      return problem;
  if (predicted.scored.empty()) return "no trial to score it on";
  return {};
}

// The measured contact onset of the run's driving trial [s, trial time].
double drive_onset(const RigInputs& in) {
  return rig::measured_onset(*in.drive_trial, in.cases.rig.sensor_deadband.value);
}

// The fitted case's --start and --end moved to the predicted case's own contact onset.
void shift_window(const RigCommonArgs& fitted_args, const RigInputs& fitted, PredictionCase& c) {
  if (!fitted_args.start && !fitted_args.end) return;
  const double shift = drive_onset(c.inputs) - drive_onset(fitted);
  if (fitted_args.start) c.args.start = *fitted_args.start + shift;
  if (fitted_args.end) c.args.end = *fitted_args.end + shift;
}

}  // namespace

rig::RunParameters with_values(rig::RunParameters p, const std::vector<rig::SearchParameter>& s,
                               const std::vector<double>& x) {
  for (size_t i = 0; i < s.size(); ++i) rig::set_parameter(p, s[i].name, x[i]);
  return p;
}

std::vector<RigRunJob> runs_at(const RigInputs& in, const RigCommonArgs& args,
                               const std::vector<rig::SearchParameter>& s,
                               const std::vector<std::vector<double>>& points,
                               const std::function<std::string(size_t)>& label) {
  std::vector<RigRunJob> runs;
  for (size_t k = 0; k < points.size(); ++k)
    runs.push_back({&in, &args, with_values(in.parameters, s, points[k]), label(k)});
  return runs;
}

std::vector<PredictionCase> read_prediction_cases(const RigCalibrateArgs& args,
                                                  const RigInputs& fitted,
                                                  const std::vector<rig::SearchParameter>& params) {
  const std::vector<std::string> codes = split_codes(args.predict);
  std::vector<PredictionCase> out;
  out.reserve(codes.size());  // RigInputs points into itself: never moved once read
  for (const std::string& code : codes) {
    RigCommonArgs a = args.common;
    a.case_code = code;
    a.fields = false;
    out.push_back({a, read_rig_inputs(a)});
    if (const std::string problem = check_prediction(code, fitted, out.back().inputs, params);
        !problem.empty())
      throw std::invalid_argument(fmt::format("--predict {}: {}", code, problem));
    shift_window(args.common, fitted, out.back());
  }
  return out;
}

std::vector<int> read_fit_trials(const RigCalibrateArgs& args, const RigInputs& in) {
  std::vector<int> fit;
  std::vector<int> scored;
  for (const rig::MeasuredTrial& t : in.scored) scored.push_back(t.trial);
  const std::string which =
      fmt::format("{} is scored on {}", in.rig_case->code, scored_trials_text(in));
  for (const std::string& word : split_codes(args.fit_trials)) {
    int trial = 0;
    const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), trial);
    if (ec != std::errc() || end != word.data() + word.size())
      throw std::invalid_argument(fmt::format("--fit-trials {}: not a trial number", word));
    if (std::find(scored.begin(), scored.end(), trial) == scored.end())
      throw std::invalid_argument(
          fmt::format("--fit-trials {}: not a trial the run is scored on ({})", trial, which));
    if (std::find(fit.begin(), fit.end(), trial) != fit.end())
      throw std::invalid_argument(fmt::format("--fit-trials {}: named twice", trial));
    fit.push_back(trial);
  }
  if (!fit.empty() && fit.size() == scored.size())
    throw std::invalid_argument(fmt::format(
        "--fit-trials {}: leaves no trial out of the fit ({}); leave it out to fit them all",
        args.fit_trials, which));
  return fit;
}

std::optional<double> fitted_objective(const RigRunOutcome& o, const std::vector<int>& fit) {
  if (fit.empty() || !o.comparison) return o.objective;
  return rig::calibration_objective(*o.comparison, fit);
}

std::vector<db::RigCalibrationTrial> trial_scores(const RigInputs& in, const std::vector<int>& fit,
                                                  const RigRunOutcome& before,
                                                  const RigRunOutcome& after) {
  auto alone = [](const RigRunOutcome& o, int trial) -> std::optional<double> {
    if (!o.comparison) return std::nullopt;
    return rig::calibration_objective(*o.comparison, std::vector<int>{trial});
  };
  std::vector<db::RigCalibrationTrial> out;
  for (const rig::MeasuredTrial& t : in.scored)
    out.push_back({t.trial, fit.empty() || std::find(fit.begin(), fit.end(), t.trial) != fit.end(),
                   alone(before, t.trial), alone(after, t.trial)});
  return out;
}

void print_trial_scores(const std::vector<db::RigCalibrationTrial>& trials,
                        const RigRunOutcome& before, const RigRunOutcome& after) {
  std::vector<int> left_out;
  for (const db::RigCalibrationTrial& t : trials)
    if (!t.fitted) left_out.push_back(t.trial);
  if (left_out.empty()) return;
  auto text = [](const std::optional<double>& v) {
    return v ? fmt::format("{:.5f}", *v) : std::string("-");
  };
  fmt::print("\nTrials of the fitted case ({} over each trial alone)\n", rig::kObjectiveName);
  fmt::print("  {:<6} {:<10} {:>12} {:>12}\n", "trial", "", "start", "calibrated");
  for (const db::RigCalibrationTrial& t : trials)
    fmt::print("  {:<6} {:<10} {:>12} {:>12}\n", t.trial, t.fitted ? "fitted" : "left out",
               text(t.objective_before), text(t.objective_after));
  auto together = [&](const RigRunOutcome& o) -> std::optional<double> {
    if (!o.comparison) return std::nullopt;
    return rig::calibration_objective(*o.comparison, left_out);
  };
  fmt::print("  left out of the fit, together: {} -> {}\n", text(together(before)),
             text(together(after)));
}

std::vector<rig::ParameterSpread> profile_calibration(
    const RigInputs& in, const RigCommonArgs& args, const std::vector<rig::SearchParameter>& params,
    const std::vector<int>& fit, const std::vector<double>& best, double best_objective, int jobs) {
  const rig::BatchObjective objective = [&](const std::vector<std::vector<double>>& points) {
    const std::vector<RigRunJob> runs = runs_at(in, args, params, points, [&](size_t k) {
      return fmt::format("{} profile {}", in.rig_case->code, k + 1);
    });
    std::vector<std::optional<double>> values;
    for (const RigRunOutcome& o : run_rig_batch(runs, jobs))
      values.push_back(o.result.summary.verdict == Verdict::completed ? fitted_objective(o, fit)
                                                                      : std::nullopt);
    return values;
  };
  std::vector<rig::ParameterSpread> spread =
      rig::profile_parameters(params, best, best_objective, objective, rig::ProfileSettings{});
  for (const rig::ParameterSpread& s : spread)
    if (s.on_lower_bound || s.on_upper_bound)
      fmt::print(stderr,
                 "ccm: warning: {} ended on its {} bound ({:g}): its best may lie beyond; widen "
                 "--bounds {}=lo:hi\n",
                 s.name, s.on_lower_bound ? "lower" : "upper", s.best, s.name);
  return spread;
}

void print_spread(const std::vector<rig::ParameterSpread>& spread) {
  if (spread.empty()) return;
  fmt::print(
      "\nSpread ({:.0f} % rise of the objective; a sensitivity, not a confidence interval)\n",
      100.0 * rig::ProfileSettings{}.rise);
  fmt::print("  {:<22} {:>12} {:>12} {:>12}\n", "parameter", "best", "+-", "curvature");
  for (const rig::ParameterSpread& s : spread) {
    const std::string width = s.half_width  ? fmt::format("{:.4g}", *s.half_width)
                              : s.curvature ? std::string("unidentified")
                                            : std::string("- (a run failed)");
    fmt::print("  {:<22} {:>12.6g} {:>12} {:>12}\n", s.name, s.best, width,
               s.curvature ? fmt::format("{:.4g}", *s.curvature) : std::string("-"));
  }
}

std::vector<Prediction> run_predictions(const std::vector<PredictionCase>& cases,
                                        const std::vector<rig::SearchParameter>& params,
                                        const std::vector<double>& best, int jobs) {
  std::vector<double> start;
  for (const rig::SearchParameter& p : params) start.push_back(p.initial);
  std::vector<RigRunJob> runs;  // per case: the start's run, then the calibrated one
  for (const PredictionCase& c : cases) {
    const RigInputs& in = c.inputs;
    runs.push_back(
        {&in, &c.args, with_values(in.parameters, params, start), in.rig_case->code + " start"});
    runs.push_back({&in, &c.args, with_values(in.parameters, params, best),
                    in.rig_case->code + " calibrated"});
  }
  std::vector<RigRunOutcome> done = run_rig_batch(runs, jobs);
  std::vector<Prediction> out;
  for (size_t k = 0; k < cases.size(); ++k)
    out.push_back({&cases[k], std::move(done[2 * k]), std::move(done[2 * k + 1])});
  return out;
}

void print_predictions(const std::vector<Prediction>& predictions) {
  if (predictions.empty()) return;
  fmt::print("\nLeft out of the fit ({})\n", rig::kObjectiveName);
  fmt::print("  {:<8} {:>12} {:>12}  scored on\n", "case", "start", "calibrated");
  for (const Prediction& p : predictions) {
    const RigInputs& in = p.predicted->inputs;
    const rig::RunWindow& w = p.calibrated.result.window;
    fmt::print("  {:<8} {:>12} {:>12}  {}; window {:.9g} to {:.9g} s\n", in.rig_case->code,
               objective_text(p.start), objective_text(p.calibrated), scored_trials_text(in),
               w.start, w.end);
  }
}

}  // namespace ccm
