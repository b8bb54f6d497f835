// From a parsed Scene to what run_explicit needs: the Model (meshes, boundary conditions, initial
// velocities, gravity), the output request and the time and monitor settings.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "engine/bc/kinematic_constraint.hpp"
#include "engine/contact/contact_model.hpp"
#include "engine/observe/history.hpp"
#include "engine/solver/explicit_integrator.hpp"
#include "engine/solver/model.hpp"
#include "run/scene/scene.hpp"

namespace ccm {

// Meshes every body (Gmsh) and applies fixed nodes, surface loads, initial velocities and gravity.
// Throws ConfigError naming the scene file, line and key when a body cannot be meshed (the
// message names the body and the mesh file), a body name is unknown, a selection selects no
// node or a load surface has no area.
Model build_model(const Scene& scene);

// The scene's [[surface_loads]] on `model` (build_model's; a model built elsewhere gets them from
// assemble_scene_run). Throws ConfigError as build_model does.
void apply_surface_loads(const Scene& scene, Model& model);

// The histories the scene asks for; tracked points become the nearest node of their body.
// Throws ConfigError for an unknown body name.
OutputRequest build_output_request(const Scene& scene, const ModelMesh& mesh);

TimeControl time_control(const SceneTime& time);

// The contact model a scene's [contact] table asks for, or the set of one model per entry of
// [[contact.pairs]]; no model for "none" (or no table).
struct ContactSetup {
  std::unique_ptr<ContactModel> model;          // null: no contact
  std::vector<const HistorySource*> histories;  // the models' history columns
  std::string model_name = "none";  // "none", "dcr", "rigid_penalty"; a set joins with " + "
  std::string description;          // one line for the run summary
  // Non-empty after a run when some contact solves stopped at their sweep cap without
  // converging (DCR): a warning for the run summary, with the counts.
  std::function<std::string()> solve_warning;
  // After a run: what the contact search did (DCR: the steps its broad phase ran on, the pair
  // cache's rebuilds), for the run summary; empty for none.
  std::function<std::string()> search_summary;
};

// Throws ConfigError naming the scene file, line and key for an unknown body, a surface that does
// not exist or is not on that body, or an empty surface.
ContactSetup build_contact(const Scene& scene, const Model& model);

// The scene's [[joints]], in file order. Throws ConfigError naming the scene file, line and key
// for a selection that selects no node or a rigid body's, or a pin whose nodes all lie on its
// axis.
std::vector<std::unique_ptr<KinematicConstraint>> build_joints(const Scene& scene,
                                                               const Model& model);

}  // namespace ccm
