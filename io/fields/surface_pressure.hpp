// Contact pressure on boundary triangles from nodal contact forces (docs/fields.md):
//   A_i = sum over the triangles f around node i of A_f / 3        (current areas)
//   t_f = 1/3 sum over the nodes i of f of F_i / A_i               (traction on f)
//   p_f = -t_f . n_f                                               (compressive positive)
// so that sum_f t_f A_f = sum_i F_i: the tractions carry exactly the nodal forces. A node where
// faces of different orientation meet (an edge of a box) shares its force with all of them, so
// the pressure along such an edge of a contact patch is smeared over both sides.
#pragma once

#include <span>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/mesh/tet_mesh.hpp"

namespace ccm::fields {

// force: one entry per global node (only the triangles' nodes are read) [N]; x: positions [m].
// Returns p_f [Pa] per triangle; t_f [Pa] per triangle into `traction` when it is not null.
std::vector<double> face_contact_pressure(std::span<const Triangle> faces, std::span<const Vec3> x,
                                          std::span<const Vec3> force,
                                          std::vector<Vec3>* traction = nullptr);

}  // namespace ccm::fields
