// From a Gmsh mesh of several parts (a TetMesh with named regions, sharing the nodes of their
// interfaces) to engine bodies: one body per part with the part's material, so that a part
// keeps its own density and modulus while the parts stay joined.
//
// The engine's bodies own contiguous node ranges; here a node on an interface is owned by the
// first part (in region order) whose tets use it, and the tets of the later part reference it
// there. Body.boundary is the boundary of the part's own tets, its interfaces included: contact
// surfaces must therefore be named explicitly (they are, see rig_model.hpp).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "engine/mesh/model_mesh.hpp"

namespace ccm::rig {

struct AssembledParts {
  std::vector<int> body;                             // the body index of each region of the TetMesh
  std::vector<int> node;                             // the model node of each TetMesh node
  std::map<std::string, std::vector<int>> nodes_of;  // every node a part's tets use, sorted
};

// Appends the regions of `mesh` to `model`, each as a body named by its region, with the
// material `materials.at(region name)`. Throws std::invalid_argument when the mesh has no
// regions or a region has no material.
AssembledParts add_parts(ModelMesh& model, const TetMesh& mesh,
                         const std::map<std::string, MaterialParams>& materials);

}  // namespace ccm::rig
