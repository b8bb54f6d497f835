// A Gmsh sphere whose mesh is refined around one pole, for contact tests that must resolve a
// small contact patch (Hertz: >= 8-10 surface elements across the contact radius,
// docs/contact-method.md §6(a)) without paying for that resolution in the whole sphere.
#pragma once

#include "engine/core/types.hpp"
#include "engine/mesh/tet_mesh.hpp"

namespace ccm::test {

struct RefinedSphere {
  double radius = 0.01;
  double h_max = 0.002;         // element size away from the pole
  double h_min = 0.0005;        // element size at the pole
  double refined_radius = 0.0;  // half-width of the box around the pole meshed at h_min
  double transition = 0.003;    // distance over which the size grows from h_min to h_max
};

// Meshes the sphere with its refined pole at centre + R * (0, 0, pole_sign) (pole_sign +1 or -1).
// Deterministic (Gmsh Delaunay); throws MeshError when Gmsh fails.
TetMesh refined_sphere(const RefinedSphere& spec, const Vec3& centre, int pole_sign);

}  // namespace ccm::test
