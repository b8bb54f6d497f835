#include "app/validate_command.hpp"

#include <fmt/format.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "app/json_output.hpp"
#include "app/output_file.hpp"
#include "app/progress_line.hpp"
#include "app/run_command.hpp"
#include "bench_test/bench_scores.hpp"
#include "bench_test/bench_trials.hpp"
#include "bench_test/scene_observable.hpp"
#include "config/config_error.hpp"
#include "engine/threads/thread_count.hpp"
#include "run/scene/scene_file.hpp"
#include "run/scene/scene_run.hpp"

namespace ccm {
namespace {

namespace fs = std::filesystem;

// Everything read and checked before the run.
struct Prepared {
  bench::BenchMapping mapping;
  std::vector<bench::PreparedTrial> trials;
  SceneRun run;
  std::unique_ptr<HistoryRecorder> history;
  std::vector<bench::ResolvedObservable> observables;  // one per channel
};

Prepared prepare(const ValidateArgs& args) {
  const fs::path mapping_file = args.data / bench::kMappingFileName;
  if (!fs::is_directory(args.data))
    throw std::invalid_argument(fmt::format("--data {}: not a folder", args.data.string()));
  if (!fs::exists(mapping_file))
    throw std::invalid_argument(fmt::format(
        "--data {}: has no {} (the mapping from measured channels to the scene's outputs, "
        "docs/bench-test.md)",
        args.data.string(), bench::kMappingFileName));
  bench::BenchMapping mapping = bench::read_bench_mapping(mapping_file);
  std::vector<bench::PreparedTrial> trials =
      bench::prepare_trials(mapping, bench::read_bench_trials(mapping));
  Prepared p{std::move(mapping),
             std::move(trials),
             assemble_scene_run(parse_scene_file(args.scene)),
             nullptr,
             {}};
  p.history = std::make_unique<HistoryRecorder>(p.run.model.mesh, p.run.output);
  // The options add the contact's history columns: the observables are looked up after them.
  (void)scene_run_options(p.run, p.history.get());
  for (const bench::ChannelSpec& c : p.mapping.channels)
    p.observables.push_back(bench::resolve_observable(c, p.history->columns(), p.mapping.file));
  return p;
}

nlohmann::json score_json(const bench::ChannelScore& s) {
  nlohmann::json j = {{"against", s.against},
                      {"samples", s.samples},
                      {"nrmse", s.nrmse ? nlohmann::json(*s.nrmse) : nlohmann::json()},
                      {"peak_measured", s.peak_measured},
                      {"peak_simulated", s.peak_simulated},
                      {"peak_error", s.peak_error},
                      {"peak_time_error", s.peak_time_error}};
  const correlate::CurveRating& r = s.rating;
  j["iso18571"] = {{"corridor", r.corridor},
                   {"phase", r.phase},
                   {"magnitude", r.magnitude},
                   {"slope", r.slope},
                   {"overall", r.overall},
                   {"grade", correlate::grade_name(r.grade)},
                   {"shift_samples", r.shift_samples}};
  return j;
}

nlohmann::json validation_json(const ValidateArgs& args, const RunSummary& run,
                               const bench::BenchScores& scores) {
  nlohmann::json channels = nlohmann::json::array();
  for (const bench::ChannelResult& c : scores.channels) {
    nlohmann::json trials = nlohmann::json::array();
    for (const bench::ChannelScore& s : c.trials) trials.push_back(score_json(s));
    channels.push_back({{"channel", c.channel}, {"mean", score_json(c.mean)}, {"trials", trials}});
  }
  return {
      {"scene", args.scene.string()},
      {"data", args.data.string()},
      {"iso18571_edition", "ISO/TS 18571:2024 procedure, default parameters (docs/correlation.md)"},
      {"run",
       {{"verdict", to_string(run.verdict)},
        {"steps", run.steps},
        {"wall_seconds", run.wall_seconds}}},
      {"clock_shifts", scores.clock_shifts},
      {"channels", channels}};
}

std::string curves_csv(const bench::ChannelCurves& c) {
  std::string out = "time,simulated,mean,low,high\n";
  for (std::size_t k = 0; k < c.t.size(); ++k)
    out += fmt::format("{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", c.t[k], c.simulated[k],
                       c.mean[k], c.low[k], c.high[k]);
  return out;
}

std::string nrmse_text(const std::optional<double>& v) {
  return v ? fmt::format("{:.3f}", *v) : std::string("-");
}

void print_tables(const bench::BenchScores& scores, const bench::BenchMapping& m) {
  fmt::print("clock shifts onto the simulation [ms]:");
  for (double s : scores.clock_shifts) fmt::print(" {:+.3f}", 1e3 * s);
  fmt::print("\n\n{:<14} {:<22} {:>7} {:>8} {:>8} {:>6} {:>6} {:>6} {:>6} {:>7}  {}\n", "channel",
             "against", "nRMSE", "peak err", "t_pk ms", "Z", "E_P", "E_M", "E_S", "rating",
             "grade");
  for (const bench::ChannelResult& c : scores.channels) {
    const bench::ChannelSpec& spec = *m.channel(c.channel);
    auto row = [&](const bench::ChannelScore& s) {
      const correlate::CurveRating& r = s.rating;
      const double rel = s.peak_measured != 0.0 ? s.peak_error / std::abs(s.peak_measured) : 0.0;
      fmt::print(
          "{:<14} {:<22} {:>7} {:>+7.1f}% {:>+8.3f} {:>6.3f} {:>6.3f} {:>6.3f} {:>6.3f} "
          "{:>7.3f}  {}\n",
          c.channel, s.against, nrmse_text(s.nrmse), 100.0 * rel, 1e3 * s.peak_time_error,
          r.corridor, r.phase, r.magnitude, r.slope, r.overall, correlate::grade_name(r.grade));
    };
    for (const bench::ChannelScore& s : c.trials) row(s);
    row(c.mean);
    (void)spec;
  }
}

int validate(const ValidateArgs& args) {
  set_default_threads(resolve_threads(args.threads, available_cores()));
  Prepared p = prepare(args);
  const fs::path out =
      args.out.empty() ? fs::path("validate-" + args.scene.stem().string()) : args.out;
  if (fs::exists(out) && !fs::is_directory(out))
    throw std::invalid_argument(
        fmt::format("--out {}: exists and is not a directory", out.string()));

  RunOptions options = scene_run_options(p.run, p.history.get());
  ProgressLine progress("validate");
  options.progress = progress.on_terminal(args.quiet);
  const RunSummary run = run_explicit(p.run.model, options);
  progress.finish();
  fs::create_directories(out);
  write_history_csv(out / "history.csv", *p.history);
  if (run.verdict == Verdict::unstable) {
    fmt::print(stderr, "ccm: the run went unstable at t = {:.6g} s: {}\n", run.instability.time,
               run.instability.reason);
    return exit_code::unstable;
  }
  std::map<std::string, rig::TimeSeries> simulated;
  for (std::size_t i = 0; i < p.mapping.channels.size(); ++i)
    simulated[p.mapping.channels[i].name] =
        bench::simulated_curve(p.mapping.channels[i], p.observables[i], p.history->rows());
  const bench::BenchScores scores = bench::score_bench_test(p.mapping, p.trials, simulated);
  const nlohmann::json j = validation_json(args, run, scores);
  write_atomic(out / "validation.json", j.dump(2) + "\n");
  for (const bench::ChannelResult& c : scores.channels)
    write_atomic(out / (c.channel + ".csv"), curves_csv(c.curves));
  if (args.json)
    print_json(j);
  else {
    print_tables(scores, p.mapping);
    fmt::print("\n  written: {}/validation.json, history.csv and one CSV per channel\n",
               out.string());
  }
  return exit_code::completed;
}

}  // namespace

int validate_command(const ValidateArgs& args) {
  try {
    return validate(args);
  } catch (const ConfigError& e) {
    fmt::print(stderr, "ccm: error: {}\n", e.what());
    return exit_code::bad_input;
  } catch (const std::invalid_argument& e) {
    fmt::print(stderr, "ccm: error: {}\n", e.what());
    return exit_code::bad_input;
  } catch (const std::exception& e) {
    fmt::print(stderr, "ccm: error: {}\n", e.what());
    return exit_code::internal_error;
  } catch (const std::string& e) {  // Gmsh throws its messages as strings
    fmt::print(stderr, "ccm: internal error: {}\n", e);
    return exit_code::internal_error;
  }
}

}  // namespace ccm
