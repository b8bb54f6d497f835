// The rig's parts meshed by Gmsh (OpenCASCADE kernel) from rig_models/geometry.toml, each a
// TetMesh whose named regions are the parts (a conforming mesh: parts share the nodes of their
// interfaces). Frame as in rig_geometry.hpp. Every size is multiplied by `mesh_scale` (1: the
// sizes of the file; 2: twice as coarse, for quick runs).
//
//   artifact: regions "envelope" (the PVC pipe), "core_upper" (the core above core_split with
//             the upper stabilizer and the bore of the pin), "core_lower" (below, with the lower
//             stabilizer); the envelope refined within contact_zone of the contact point.
//   impactor: regions "carriage", "rod" and, for the flexible impactor, "spring" (the cylinder
//             of eq. 3.1 between the carriage's front face and the rod); the rod's tip at
//             y = tip_y on the axis (0, y, -pivot_to_sensor). The rigid impactor's rod is
//             longer by the spring's length (the wooden block behind it, thesis 3.2.2).
//   spring:   the spring cylinder alone, from z = 0 to z = spring_length (for the check of K_s).
#pragma once

#include "engine/mesh/tet_mesh.hpp"
#include "rig_models/cases/rig_case.hpp"
#include "rig_models/geometry/rig_geometry.hpp"

namespace ccm::rig {

TetMesh mesh_artifact(const RigGeometry& geometry, const RigParameters& rig, double mesh_scale);

TetMesh mesh_impactor(const RigGeometry& geometry, const RigParameters& rig, ImpactorKind kind,
                      double tip_y, double mesh_scale);

TetMesh mesh_spring(const RigGeometry& geometry, const RigParameters& rig, double mesh_scale);

}  // namespace ccm::rig
