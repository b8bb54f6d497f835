#include "app/rig_runner.hpp"

#include "app/progress_line.hpp"
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
  o.result = rig::run_rig({in.cases, in.geometry}, *in.rig_case, req);
  progress.finish();
  o.ended_at = utc_timestamp_now();
  compare_with_trials(in, o);
  return o;
}

}  // namespace ccm
