#include "app/rig_runner.hpp"

#include <memory>

#include "app/progress_line.hpp"
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
  // --fields: the recorder is made once the model is built (rig_run.hpp `instrument`).
  std::unique_ptr<fields::FieldRecorder> recorder;
  if (args.fields && args.out)
    req.instrument = [&](const Model& model, RunOptions& options) {
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
