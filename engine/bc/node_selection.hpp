// Geometric selections of nodes in the reference configuration.
#pragma once

#include <vector>

#include "engine/mesh/model_mesh.hpp"

namespace ccm {

// Nodes of body `body` (all bodies when -1) with lo <= X <= hi componentwise.
std::vector<int> nodes_in_box(const ModelMesh& mesh, int body, const Vec3& lo, const Vec3& hi);

// Nodes of body `body` (all bodies when -1) within `tolerance` of the plane through `point`
// with normal `normal` (need not be unit).
std::vector<int> nodes_on_plane(const ModelMesh& mesh, int body, const Vec3& point,
                                const Vec3& normal, double tolerance);

// Boundary triangles of body `body` whose three nodes all lie within `tolerance` of the plane.
std::vector<Triangle> boundary_on_plane(const ModelMesh& mesh, int body, const Vec3& point,
                                        const Vec3& normal, double tolerance);

// The node of body `body` nearest to p in the reference configuration (lowest id on ties).
int nearest_node(const ModelMesh& mesh, int body, const Vec3& p);

}  // namespace ccm
