#include "app/rig_runner.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <memory>
#include <optional>
#include <thread>

#include "app/progress_line.hpp"
#include "app/setup_time.hpp"
#include "io/fields/field_recorder.hpp"
#include "records/provenance/timestamp.hpp"

namespace ccm {

RigRunOutcome run_rig_once(const RigInputs& in, const RigCommonArgs& args,
                           const rig::RunParameters& parameters, const std::string& label) {
  RigRunOutcome o;
  o.parameters = parameters;
  o.started_at = utc_timestamp_now();
  rig::RigRunRequest req;
  req.drive = in.drive;
  req.trial = in.drive_trial;
  req.start = args.start;
  req.end = args.end;
  req.mesh_scale = args.mesh_scale;
  req.parameters = parameters;
  ProgressLine progress(label);
  req.progress = progress.on_terminal(args.quiet);
  // The set-up ends when the model is built (rig_run.hpp `instrument`); with --fields, the
  // recorder is made then.
  std::unique_ptr<fields::FieldRecorder> recorder;
  const MeshCacheStats before = mesh_cache_stats();
  const auto start = std::chrono::steady_clock::now();
  req.instrument = [&](const Model& model, RunOptions& options) {
    o.setup_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    o.meshing = mesh_cache_delta(before, mesh_cache_stats());
    if (!args.fields || !args.out) return;
    std::filesystem::create_directories(*args.out);
    const double interval =
        args.field_interval.value_or(kRigFieldEvery * options.time.output_interval);
    recorder = std::make_unique<fields::FieldRecorder>(
        model,
        fields::FieldRequest{fields::all_fields(), interval, "ccm rig run " + in.rig_case->code},
        *args.out);
    recorder->attach(options);
  };
  o.result = rig::run_rig({in.cases, in.geometry}, *in.rig_case, req);
  if (recorder) recorder->finish();
  progress.finish();
  o.ended_at = utc_timestamp_now();
  compare_with_trials(in, o);
  return o;
}

std::vector<RigRunOutcome> run_rig_batch(const std::vector<RigRunJob>& jobs, int at_once) {
  const size_t threads = std::min(jobs.size(), static_cast<size_t>(std::max(at_once, 1)));
  std::vector<std::optional<RigRunOutcome>> done(jobs.size());
  std::vector<std::exception_ptr> failed(jobs.size());
  std::atomic<size_t> next{0};
  std::atomic<bool> stop{false};
  auto work = [&](bool show_progress) {
    for (size_t k = next++; k < jobs.size() && !stop; k = next++) {
      const RigRunJob& j = jobs[k];
      RigCommonArgs args = *j.args;
      args.quiet = args.quiet || !show_progress;
      try {
        done[k] = run_rig_once(*j.inputs, args, j.parameters, j.label);
      } catch (...) {
        failed[k] = std::current_exception();
        stop = true;  // no run starts after a failure
      }
    }
  };
  if (threads <= 1) {
    work(true);
  } else {
    std::vector<std::thread> workers;
    for (size_t t = 0; t < threads; ++t) workers.emplace_back(work, false);
    for (std::thread& w : workers) w.join();
  }
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
  std::vector<RigRunOutcome> out;
  for (std::optional<RigRunOutcome>& o : done) out.push_back(std::move(*o));
  return out;
}

}  // namespace ccm
