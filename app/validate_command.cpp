#include "app/validate_command.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "app/bench_run.hpp"
#include "app/command_errors.hpp"
#include "app/json_output.hpp"
#include "app/output_file.hpp"
#include "app/progress_line.hpp"
#include "app/run_command.hpp"
#include "app/validate_fit.hpp"
#include "app/validate_output.hpp"
#include "app/validate_record.hpp"
#include "config/config_error.hpp"
#include "db/sqlite/connection.hpp"
#include "engine/threads/thread_count.hpp"
#include "run/scene/scene_file.hpp"

namespace ccm {
namespace {

namespace fs = std::filesystem;

fs::path out_folder(const ValidateArgs& args) {
  const fs::path out =
      args.out.empty() ? fs::path("validate-" + args.scene.stem().string()) : args.out;
  if (fs::exists(out) && !fs::is_directory(out))
    throw std::invalid_argument(
        fmt::format("--out {}: exists and is not a directory", out.string()));
  return out;
}

int validate(const ValidateArgs& args) {
  set_default_threads(resolve_threads(args.threads, available_cores()));
  const BenchData data = load_bench_data(args.data);
  const fs::path store = validation_store(args);
  if (!args.fit.empty()) return validate_fit(args, data, out_folder(args), store);
  BenchRun bench(parse_scene_file(args.scene), data.mapping);
  const fs::path out = out_folder(args);

  ProgressLine progress("validate");
  const RunSummary& run = bench.run(progress.on_terminal(args.quiet));
  progress.finish();
  fs::create_directories(out);
  write_history_csv(out / "history.csv", bench.history());
  if (run.verdict == Verdict::unstable) {
    fmt::print(stderr, "ccm: the run went unstable at t = {:.6g} s: {}\n", run.instability.time,
               run.instability.reason);
    return exit_code::unstable;
  }
  const std::optional<bench::BenchScores> scores =
      scored(data.mapping, data.trials, bench.simulated());
  if (!scores) return exit_code::unstable;
  nlohmann::json j = scores_json(*scores);
  j["scene"] = args.scene.string();
  j["data"] = args.data.string();
  j["run"] = {{"verdict", to_string(run.verdict)},
              {"steps", run.steps},
              {"wall_seconds", run.wall_seconds}};
  const db::ValidationRow row = validation_row(args, data, *scores, {}, j);
  j["store"] = record_validation_row(store, row);
  write_atomic(out / "validation.json", j.dump(2) + "\n");
  write_channel_curves(out, *scores);
  write_validation_figures(out, row);
  if (args.json)
    print_json(j);
  else {
    print_scores(*scores);
    fmt::print("\n  written: {}/validation.json, history.csv and one CSV per channel\n  {}\n",
               out.string(), j["store"].get<std::string>());
  }
  return exit_code::completed;
}

}  // namespace

int validate_command(const ValidateArgs& args) {
  return run_scene_command([&] { return validate(args); });
}

}  // namespace ccm
