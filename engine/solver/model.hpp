// Everything a run needs, built once before it starts: mesh, element data, boundary
// conditions and initial velocities. A plain aggregate; the integrator does the work.
#pragma once

#include <vector>

#include "engine/bc/boundary_conditions.hpp"
#include "engine/body/rigid_body_model.hpp"
#include "engine/element/internal_force.hpp"
#include "engine/mesh/model_mesh.hpp"

namespace ccm {

struct Model {
  ModelMesh mesh;
  ElementSet elements;
  BoundaryConditions bcs;
  std::vector<Vec3> initial_velocity;  // per node
  // One per body of the mesh marked rigid (Body::rigid), in body order.
  std::vector<RigidBodyModel> rigid_bodies;
};

// Builds the element set and sets the initial velocities to zero. Throws std::runtime_error
// when an element has no positive reference volume.
Model make_model(ModelMesh mesh);

}  // namespace ccm
