// A linear-tetrahedron mesh of one or more bodies, in the reference configuration.
#pragma once

#include <Eigen/Geometry>  // cross
#include <array>
#include <map>
#include <string>
#include <vector>

#include "engine/core/types.hpp"

namespace ccm {

using Tet = std::array<int, 4>;       // node indices; positive reference volume
using Triangle = std::array<int, 3>;  // node indices; counter-clockwise seen from outside

// Geometry as it comes from a mesher or a mesh file: nodes, tets, the named surfaces the file or
// primitive defines (physical groups of dimension 2, UNV groups of triangles, Abaqus *SURFACE),
// the named node sets a file defines beyond its surfaces (UNV node groups, Abaqus *NSET) and, for
// a model of several volumes, the named region of every tet (physical groups of dimension 3).
struct TetMesh {
  std::vector<Vec3> nodes;
  std::vector<Tet> tets;
  std::map<std::string, std::vector<Triangle>> named_surfaces;
  std::map<std::string, std::vector<int>> named_node_sets;  // sorted unique node indices
  std::vector<std::string> region_names;                    // empty: the mesh is one region
  std::vector<int> tet_region;  // per tet, an index into region_names (or empty)

  int n_nodes() const { return static_cast<int>(nodes.size()); }
  int n_elements() const { return static_cast<int>(tets.size()); }
};

// Six times the signed volume of tet t: det[x1 - x0, x2 - x0, x3 - x0].
inline double six_volume(const Tet& t, const std::vector<Vec3>& x) {
  const Vec3& x0 = x[static_cast<size_t>(t[0])];
  return (x[static_cast<size_t>(t[1])] - x0)
      .cross(x[static_cast<size_t>(t[2])] - x0)
      .dot(x[static_cast<size_t>(t[3])] - x0);
}

// The reference volume of the mesh: sum over tets of six_volume / 6 [m^3].
inline double mesh_volume(const TetMesh& mesh) {
  double v = 0.0;
  for (const Tet& t : mesh.tets) v += six_volume(t, mesh.nodes);
  return v / 6.0;
}

}  // namespace ccm
