#include "app/validate_fit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>

#include "app/json_output.hpp"
#include "app/output_file.hpp"
#include "app/progress_line.hpp"
#include "app/run_command.hpp"
#include "app/validate_output.hpp"
#include "app/validate_record.hpp"
#include "config/strict_table.hpp"
#include "config/text_file.hpp"
#include "rig_models/calibrate/bounded_search.hpp"
#include "rig_models/calibrate/parameter_profile.hpp"
#include "run/scene/scene_file.hpp"
#include "run/template/scene_paths.hpp"

namespace ccm {
namespace {

namespace fs = std::filesystem;

double number_of(std::string_view text, std::string_view arg) {
  try {
    std::size_t used = 0;
    const std::string s(text);
    const double v = std::stod(s, &used);
    if (used == s.size() && std::isfinite(v)) return v;
  } catch (const std::exception&) {
  }
  throw std::invalid_argument(
      fmt::format("--fit {}: '{}' is not a number (the form is PATH=LO:HI)", arg, text));
}

// The trials fitted to (indices into data.trials) and those left out.
std::pair<std::vector<std::size_t>, std::vector<std::size_t>> split_trials(const ValidateArgs& args,
                                                                           std::size_t count) {
  std::vector<std::size_t> fit, left_out;
  if (args.cross_validate) {
    if (!args.fit_trials.empty())
      throw std::invalid_argument(
          "--cross-validate leaves each trial out in turn: it takes no --fit-trials");
    if (count < 2) throw std::invalid_argument("--cross-validate needs at least two trials");
    for (std::size_t i = 0; i < count; ++i) fit.push_back(i);
    return {fit, left_out};
  }
  if (args.fit_trials.empty()) {
    for (std::size_t i = 0; i < count; ++i)
      (i + 1 < count || count == 1 ? fit : left_out).push_back(i);
    return {fit, left_out};
  }
  std::set<std::size_t> chosen;
  for (int k : args.fit_trials) {
    if (k < 1 || static_cast<std::size_t>(k) > count)
      throw std::invalid_argument(fmt::format(
          "--fit-trials {}: the bench test has trials 1 to {} (in file-name order)", k, count));
    chosen.insert(static_cast<std::size_t>(k - 1));
  }
  for (std::size_t i = 0; i < count; ++i) (chosen.count(i) ? fit : left_out).push_back(i);
  return {fit, left_out};
}

std::vector<bench::PreparedTrial> subset(const std::vector<bench::PreparedTrial>& all,
                                         const std::vector<std::size_t>& which) {
  std::vector<bench::PreparedTrial> out;
  for (std::size_t i : which) out.push_back(all[i]);
  return out;
}

// The mean over the channels of the nRMSE against the trials' mean curve (the objective).
std::optional<double> mean_nrmse(const bench::BenchScores& scores) {
  double sum = 0.0;
  for (const bench::ChannelResult& c : scores.channels) {
    // a constant measured curve has no nRMSE; an event no trial has, no mean
    if (!c.mean || !c.mean->nrmse) return std::nullopt;
    sum += *c.mean->nrmse;
  }
  return sum / static_cast<double>(scores.channels.size());
}

struct Fitting {
  const ValidateArgs& args;
  const BenchData& data;
  toml::table doc;
  std::vector<FitArgument> fits;
  std::vector<bench::PreparedTrial> fit_trials;
  int evaluations = 0;

  std::string text_at(const std::vector<double>& x) const {
    toml::table one = doc;
    for (std::size_t i = 0; i < fits.size(); ++i) set_number_at_path(one, fits[i].path, x[i]);
    return document_text(one);
  }

  // One run at x, scored against the fitted trials; none when it went unstable.
  std::optional<double> objective(const std::vector<double>& x) {
    ++evaluations;
    BenchRun run(parse_scene(text_at(x), args.scene), data.mapping);
    ProgressLine progress(fmt::format("fit run {}", evaluations));
    const RunSummary& s = run.run(progress.on_terminal(args.quiet));
    progress.finish();
    if (s.verdict == Verdict::unstable) return std::nullopt;
    try {
      return mean_nrmse(bench::score_bench_test(data.mapping, fit_trials, run.simulated()));
    } catch (const bench::ScoringError&) {
      return std::nullopt;  // no trigger, no overlap: a failed evaluation the search steers from
    }
  }
};

std::vector<rig::SearchParameter> search_parameters(const Fitting& f) {
  std::vector<rig::SearchParameter> out;
  for (const FitArgument& a : f.fits) {
    const std::optional<double> now = number_at_path(f.doc, a.path);
    if (!now)
      throw std::invalid_argument(fmt::format("--fit {}: {} ({})", a.path,
                                              path_problem(f.doc, a.path), f.args.scene.string()));
    // The search starts from the scene's value, or the middle of the range when it lies outside.
    const double start = *now >= a.lower && *now <= a.upper ? *now : 0.5 * (a.lower + a.upper);
    for (double v : {a.lower, a.upper}) {  // each bound gives a scene ccm accepts
      toml::table one = f.doc;
      set_number_at_path(one, a.path, v);
      try {
        parse_scene(document_text(one), f.args.scene);
      } catch (const std::exception& e) {
        throw std::invalid_argument(fmt::format(
            "--fit {}: the bound {} gives a scene ccm refuses: {}", a.path, v, e.what()));
      }
    }
    out.push_back({a.path, a.lower, a.upper, start});
  }
  return out;
}

nlohmann::json spread_json(const rig::ParameterSpread& s, const FitArgument& a) {
  return {{"path", s.name},
          {"best", s.best},
          {"lower", a.lower},
          {"upper", a.upper},
          {"half_width", s.half_width ? nlohmann::json(*s.half_width) : nlohmann::json()},
          {"curvature", s.curvature ? nlohmann::json(*s.curvature) : nlohmann::json()},
          {"on_lower_bound", s.on_lower_bound},
          {"on_upper_bound", s.on_upper_bound}};
}

// One fold of the cross-validation: fitted without one trial, scored on it.
struct Fold {
  std::string left_out;
  std::vector<double> best;
  double objective = 0.0;
  int runs = 0;
  std::vector<std::string> channels;
  std::vector<double> ratings;  // the left-out trial's ISO rating per channel; NaN: unscored
};

std::vector<Fold> cross_validate(Fitting& f, const std::vector<rig::SearchParameter>& parameters) {
  std::vector<Fold> folds;
  const std::vector<bench::PreparedTrial>& all = f.data.trials;
  for (std::size_t i = 0; i < all.size(); ++i) {
    Fold fold;
    fold.left_out = all[i].name;
    f.fit_trials.clear();
    for (std::size_t j = 0; j < all.size(); ++j)
      if (j != i) f.fit_trials.push_back(all[j]);
    const int before = f.evaluations;
    auto objective = [&](const std::vector<double>& x) { return f.objective(x); };
    const rig::SearchResult r =
        rig::bounded_search(parameters, objective, {f.args.evaluations, 1e-3});
    fold.best = r.best;
    fold.objective = r.best_objective;
    BenchRun run(parse_scene(f.text_at(r.best), f.args.scene), f.data.mapping);
    const bool stable = run.run({}).verdict != Verdict::unstable;
    fold.runs = f.evaluations - before + 1;
    std::optional<bench::BenchScores> s;
    if (stable) {
      try {
        s = bench::score_bench_test(f.data.mapping, {all[i]}, run.simulated());
      } catch (const bench::ScoringError&) {
      }
    }
    for (const bench::ChannelSpec& c : f.data.mapping.channels) fold.channels.push_back(c.name);
    for (std::size_t k = 0; k < fold.channels.size(); ++k)
      fold.ratings.push_back(s && s->channels[k].mean && s->channels[k].mean->rating
                                 ? s->channels[k].mean->rating->overall
                                 : std::numeric_limits<double>::quiet_NaN());
    folds.push_back(std::move(fold));
  }
  return folds;
}

nlohmann::json folds_json(const std::vector<Fold>& folds, const std::vector<FitArgument>& fits) {
  nlohmann::json out = nlohmann::json::array();
  for (const Fold& fold : folds) {
    nlohmann::json values = nlohmann::json::object(), ratings = nlohmann::json::object();
    for (std::size_t p = 0; p < fits.size(); ++p) values[fits[p].path] = fold.best[p];
    for (std::size_t k = 0; k < fold.channels.size(); ++k)
      ratings[fold.channels[k]] =
          std::isnan(fold.ratings[k]) ? nlohmann::json() : nlohmann::json(fold.ratings[k]);
    out.push_back({{"left_out", fold.left_out},
                   {"fitted", values},
                   {"objective", fold.objective},
                   {"runs", fold.runs},
                   {"left_out_rating", ratings}});
  }
  return out;
}

void print_folds(const std::vector<Fold>& folds, const std::vector<FitArgument>& fits) {
  fmt::print("cross-validation: each trial left out in turn (fitted on the others, rated on it)\n");
  for (const Fold& fold : folds) {
    fmt::print("  without {}:", fold.left_out);
    for (std::size_t p = 0; p < fits.size(); ++p)
      fmt::print(" {} = {:.6g}", fits[p].path, fold.best[p]);
    fmt::print(";  its rating");
    for (std::size_t k = 0; k < fold.channels.size(); ++k)
      fmt::print(" {} {:.3f}", fold.channels[k], fold.ratings[k]);
    fmt::print("\n");
  }
  for (std::size_t p = 0; p < fits.size(); ++p) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const Fold& fold : folds) {
      lo = std::min(lo, fold.best[p]);
      hi = std::max(hi, fold.best[p]);
    }
    fmt::print("  {}: {:.6g} to {:.6g} over the folds\n", fits[p].path, lo, hi);
  }
  fmt::print("\n");
}

void print_fit(const std::vector<rig::ParameterSpread>& spreads, const rig::SearchResult& r,
               int evaluations) {
  fmt::print("fitted ({}, {} runs, {}): mean nRMSE {:.4f}\n", r.algorithm, evaluations,
             r.stop_reason, r.best_objective);
  for (const rig::ParameterSpread& s : spreads) {
    fmt::print("  {} = {:.6g}", s.name, s.best);
    if (s.half_width)
      fmt::print(" +- {:.3g} (where the objective rises 5 %)", *s.half_width);
    else
      fmt::print(" (not identified: the objective does not rise around it)");
    if (s.on_lower_bound || s.on_upper_bound)
      fmt::print("  WARNING: at its {} bound; the best may lie beyond",
                 s.on_lower_bound ? "lower" : "upper");
    fmt::print("\n");
  }
  fmt::print("\n");
}

}  // namespace

FitArgument parse_fit_argument(std::string_view text) {
  const std::size_t eq = text.rfind('='), colon = text.rfind(':');
  if (eq == std::string_view::npos || colon == std::string_view::npos || colon < eq || eq == 0)
    throw std::invalid_argument(fmt::format("--fit {}: the form is PATH=LO:HI", text));
  FitArgument a{std::string(text.substr(0, eq)),
                number_of(text.substr(eq + 1, colon - eq - 1), text),
                number_of(text.substr(colon + 1), text)};
  if (!(a.upper > a.lower))
    throw std::invalid_argument(fmt::format("--fit {}: the upper bound {} must exceed the lower {}",
                                            text, a.upper, a.lower));
  return a;
}

int validate_fit(const ValidateArgs& args, const BenchData& data, const fs::path& out,
                 const fs::path& store) {
  Fitting f{args, data, parse_toml(read_config_text(args.scene), args.scene), {}, {}, 0};
  for (const std::string& a : args.fit) f.fits.push_back(parse_fit_argument(a));
  if (args.evaluations < 2)
    throw std::invalid_argument(fmt::format("--evaluations {}: at least 2", args.evaluations));
  const auto [fit_idx, left_idx] = split_trials(args, data.trials.size());
  f.fit_trials = subset(data.trials, fit_idx);
  const std::vector<rig::SearchParameter> parameters = search_parameters(f);
  // The scene at its starting values is assembled and its observables found before any run.
  {
    BenchRun check(parse_scene(f.text_at([&] {
                     std::vector<double> x;
                     for (const auto& p : parameters) x.push_back(p.initial);
                     return x;
                   }()),
                               args.scene),
                   data.mapping);
  }

  std::vector<Fold> folds;
  if (args.cross_validate) folds = cross_validate(f, parameters);
  f.fit_trials = subset(data.trials, fit_idx);
  auto objective = [&](const std::vector<double>& x) { return f.objective(x); };
  const rig::SearchResult result =
      rig::bounded_search(parameters, objective, {args.evaluations, 1e-3});
  const std::vector<rig::ParameterSpread> spreads =
      rig::profile_parameters(parameters, result.best, result.best_objective, objective);

  // The scene at the fitted values, scored on every trial.
  const std::string fitted = f.text_at(result.best);
  BenchRun best(parse_scene(fitted, args.scene), data.mapping);
  const RunSummary& run = best.run({});
  fs::create_directories(out);
  write_atomic(out / "fitted.toml", fitted);
  write_history_csv(out / "history.csv", best.history());
  if (run.verdict == Verdict::unstable) {
    fmt::print(stderr, "ccm: the run at the fitted values went unstable at t = {:.6g} s: {}\n",
               run.instability.time, run.instability.reason);
    return exit_code::unstable;
  }
  const std::optional<bench::BenchScores> maybe =
      scored(data.mapping, data.trials, best.simulated());
  if (!maybe) return exit_code::unstable;
  const bench::BenchScores& scores = *maybe;
  std::set<std::string> left_out;
  for (std::size_t i : left_idx) left_out.insert(data.trials[i].name);
  nlohmann::json j = scores_json(scores, left_out);
  nlohmann::json params = nlohmann::json::array();
  for (std::size_t i = 0; i < spreads.size(); ++i)
    params.push_back(spread_json(spreads[i], f.fits[i]));
  std::vector<std::string> fitted_to;
  for (std::size_t i : fit_idx) fitted_to.push_back(data.trials[i].name);
  j["scene"] = args.scene.string();
  j["data"] = args.data.string();
  j["fit"] = {{"parameters", params},
              {"objective", "mean over the channels of the nRMSE against the fitted trials' mean"},
              {"best_objective", result.best_objective},
              {"algorithm", result.algorithm},
              {"stop_reason", result.stop_reason},
              {"runs", f.evaluations},
              {"fitted_to", fitted_to},
              {"left_out", std::vector<std::string>(left_out.begin(), left_out.end())}};
  if (args.cross_validate) j["fit"]["cross_validation"] = folds_json(folds, f.fits);
  const db::ValidationRow row = validation_row(args, data, scores, left_out, j);
  j["store"] = record_validation_row(store, row);
  write_atomic(out / "validation.json", j.dump(2) + "\n");
  write_channel_curves(out, scores);
  write_validation_figures(out, row);
  if (args.json)
    print_json(j);
  else {
    if (args.cross_validate) print_folds(folds, f.fits);
    print_fit(spreads, result, f.evaluations);
    print_scores(scores, left_out);
    fmt::print(
        "\n  written: {}/fitted.toml, validation.json, history.csv and one CSV per channel\n  {}\n",
        out.string(), j["store"].get<std::string>());
  }
  return exit_code::completed;
}

}  // namespace ccm
