// A scene made ready to run, by the one path every caller takes (`ccm run`, the study's point
// runner, the benchtop rig's runs): the model (meshes, boundary conditions, rigid bodies), the
// output request, the contact models and the joints, each built once from the parsed scene, and the
// run options that point at them.
#pragma once

#include <memory>
#include <vector>

#include "engine/bc/kinematic_constraint.hpp"
#include "engine/observe/history.hpp"
#include "engine/solver/explicit_integrator.hpp"
#include "run/scene/scene.hpp"
#include "run/scene/scene_builder.hpp"

namespace ccm {

struct SceneRun {
  Scene scene;
  Model model;
  OutputRequest output;
  ContactSetup contact;
  std::vector<std::unique_ptr<KinematicConstraint>> joints;  // [[joints]], in file order
  // each pin's angle and rate, each track's force and sticking
  std::vector<std::unique_ptr<HistorySource>> joint_histories;
};

// Builds everything in the order each part needs the one before. Throws ConfigError naming the
// scene file, line and key for what cannot be built (scene_builder.hpp).
SceneRun assemble_scene_run(Scene scene);

// The same with the model built elsewhere (the rig's parts, meshed and tuned by its own mesher:
// rig_models/sim/rig_scene.hpp): the scene's surface loads, contact, joints and output over the
// model's named node sets and surfaces; its bodies are not read.
SceneRun assemble_scene_run(Scene scene, Model model);

// The options of its run: time, monitor, contact, joints; with a history recorder, the recorder
// and the contact's history columns in it.
RunOptions scene_run_options(const SceneRun& run, HistoryRecorder* history);

}  // namespace ccm
