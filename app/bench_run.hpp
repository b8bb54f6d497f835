// One run of a scene for a bench test (`ccm validate`, with and without --fit): the scene
// assembled, every channel's observable found in its history before the run starts, the run, and
// each channel's simulated curve.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "bench_test/bench_mapping.hpp"
#include "bench_test/bench_scores.hpp"
#include "bench_test/scene_observable.hpp"
#include "engine/observe/history.hpp"
#include "engine/solver/explicit_integrator.hpp"
#include "rig_models/signal/time_series.hpp"
#include "run/scene/scene_run.hpp"

namespace ccm {

// The mapping and the trials of a bench test folder, read, checked and prepared
// (bench_test/bench_scores.hpp); throws std::invalid_argument when the folder or its bench.toml
// is missing, ConfigError for what is wrong in them.
struct BenchData {
  bench::BenchMapping mapping;
  std::vector<bench::PreparedTrial> trials;
};
BenchData load_bench_data(const std::filesystem::path& folder);

class BenchRun {
 public:
  // Assembles the scene and finds the observables; throws ConfigError (the scene's, or the
  // mapping's naming the channel's observable) before anything runs.
  BenchRun(Scene scene, const bench::BenchMapping& mapping);
  BenchRun(const BenchRun&) = delete;  // the run options point into the assembled scene
  BenchRun& operator=(const BenchRun&) = delete;

  // Runs it once; `progress` may be empty.
  const RunSummary& run(ProgressFn progress);

  const HistoryRecorder& history() const { return *history_; }
  // Each channel's simulated curve, by name (after run()).
  std::map<std::string, rig::TimeSeries> simulated() const;

 private:
  const bench::BenchMapping* mapping_;
  SceneRun run_;
  std::unique_ptr<HistoryRecorder> history_;
  RunOptions options_;
  std::vector<bench::ResolvedObservable> observables_;
  RunSummary summary_;
};

}  // namespace ccm
