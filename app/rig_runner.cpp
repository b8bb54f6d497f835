#include "app/rig_runner.hpp"

#include <chrono>
#include <memory>

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

}  // namespace ccm
