// From a parsed Scene to what run_explicit needs: the Model (meshes, boundary conditions, initial
// velocities, gravity), the output request and the time and monitor settings.
#pragma once

#include "engine/observe/history.hpp"
#include "engine/solver/explicit_integrator.hpp"
#include "engine/solver/model.hpp"
#include "study/scene/scene.hpp"

namespace ccm {

// Meshes every body (Gmsh) and applies fixed nodes, surface loads, initial velocities and gravity.
// Throws SceneError naming the scene file, line and key when a body cannot be meshed (the
// message names the body and the mesh file), a body name is unknown, a selection selects no
// node or a load surface has no area.
Model build_model(const Scene& scene);

// The histories the scene asks for; tracked points become the nearest node of their body.
// Throws SceneError for an unknown body name.
OutputRequest build_output_request(const Scene& scene, const ModelMesh& mesh);

TimeControl time_control(const SceneTime& time);

}  // namespace ccm
