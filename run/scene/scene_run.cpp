#include "run/scene/scene_run.hpp"

#include <utility>

#include "engine/bc/pin_joint.hpp"
#include "engine/observe/joint_history.hpp"

namespace ccm {
namespace {

// The output request, contact and joints of a scene whose model is built (with its loads).
SceneRun assemble_built(Scene scene, Model model) {
  SceneRun r;
  r.scene = std::move(scene);
  r.model = std::move(model);
  r.output = build_output_request(r.scene, r.model.mesh);
  r.contact = build_contact(r.scene, r.model);
  r.joints = build_joints(r.scene, r.model);
  for (std::size_t i = 0; i < r.joints.size(); ++i) {
    const std::string& name = r.scene.joints[i].name;
    if (const auto* pin = dynamic_cast<const PinJoint*>(r.joints[i].get()))
      r.joint_histories.push_back(std::make_unique<PinJointHistory>(name, *pin));
    else if (const auto* track = dynamic_cast<const TrackFriction*>(r.joints[i].get()))
      r.joint_histories.push_back(std::make_unique<TrackFrictionHistory>(name, *track));
  }
  return r;
}

}  // namespace

SceneRun assemble_scene_run(Scene scene) {
  Model model = build_model(scene);  // its surface loads too
  return assemble_built(std::move(scene), std::move(model));
}

SceneRun assemble_scene_run(Scene scene, Model model) {
  apply_surface_loads(scene, model);
  return assemble_built(std::move(scene), std::move(model));
}

RunOptions scene_run_options(const SceneRun& run, HistoryRecorder* history) {
  RunOptions o;
  o.time = time_control(run.scene.time);
  o.monitor = run.scene.monitor;
  o.contact = run.contact.model.get();
  for (const auto& joint : run.joints) o.constraints.push_back(joint.get());
  if (history) {
    o.history = history;
    for (const HistorySource* h : run.contact.histories) history->add_source(*h);
    for (const auto& h : run.joint_histories) history->add_source(*h);
  }
  return o;
}

}  // namespace ccm
