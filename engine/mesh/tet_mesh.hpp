// A linear-tetrahedron mesh of one or more bodies, in the reference configuration.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include "engine/core/types.hpp"

namespace ccm {

using Tet = std::array<int, 4>;       // node indices; positive reference volume
using Triangle = std::array<int, 3>;  // node indices; counter-clockwise seen from outside

// Geometry as it comes from a mesher or a mesh file: nodes, tets and the named
// surfaces the file or primitive defines (physical groups of dimension 2).
struct TetMesh {
  std::vector<Vec3> nodes;
  std::vector<Tet> tets;
  std::map<std::string, std::vector<Triangle>> named_surfaces;

  int n_nodes() const { return static_cast<int>(nodes.size()); }
  int n_elements() const { return static_cast<int>(tets.size()); }
};

}  // namespace ccm
