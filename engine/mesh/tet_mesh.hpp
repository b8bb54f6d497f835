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

// Geometry as it comes from a mesher or a mesh file: nodes, tets, the named surfaces the file or
// primitive defines (physical groups of dimension 2) and, for a model of several volumes, the
// named region of every tet (physical groups of dimension 3).
struct TetMesh {
  std::vector<Vec3> nodes;
  std::vector<Tet> tets;
  std::map<std::string, std::vector<Triangle>> named_surfaces;
  std::vector<std::string> region_names;  // empty: the mesh is one region
  std::vector<int> tet_region;            // per tet, an index into region_names (or empty)

  int n_nodes() const { return static_cast<int>(nodes.size()); }
  int n_elements() const { return static_cast<int>(tets.size()); }
};

}  // namespace ccm
