// Lumped (row-sum) mass of linear tets: rho V0 / 4 to each node   (docs/equations.md "Linear
// tetrahedron").
#pragma once

#include <vector>

#include "engine/element/internal_force.hpp"
#include "engine/mesh/model_mesh.hpp"

namespace ccm {

std::vector<double> lumped_mass(const ModelMesh& mesh, const ElementSet& elements);

}  // namespace ccm
