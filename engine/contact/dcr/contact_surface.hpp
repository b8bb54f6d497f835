// The contact surface of the DCR model (thesis 2.6, the "Contact Surface" object): the nodes,
// edges and triangles of one or more named boundary surfaces, in global node ids, with the body
// that owns each feature. Built once per model; the positions come from the state every step.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "engine/mesh/model_mesh.hpp"

namespace ccm::dcr {

struct SurfaceFeatures {
  std::vector<int> nodes;                 // sorted unique global node ids on the surfaces
  std::vector<std::array<int, 2>> edges;  // unique, a < b, sorted
  std::vector<Triangle> faces;            // outward oriented (as in the mesh)
  std::vector<int> node_body, edge_body, face_body;  // owning body index of each feature

  int n_nodes() const { return static_cast<int>(nodes.size()); }
  int n_edges() const { return static_cast<int>(edges.size()); }
  int n_faces() const { return static_cast<int>(faces.size()); }
};

// The features of mesh.surfaces[name] for every name (e.g. "ball/boundary", "plate/top").
// Faces keep the mesh's orientation and the order of the surfaces as listed, then of their
// triangles; a triangle listed by two surfaces (the same three nodes) is kept once. Edges are
// the sides of the faces. Throws std::invalid_argument naming a surface that does not exist, and
// when a surface references a node outside the mesh.
SurfaceFeatures make_surface_features(const ModelMesh& mesh,
                                      const std::vector<std::string>& surface_names);

}  // namespace ccm::dcr
