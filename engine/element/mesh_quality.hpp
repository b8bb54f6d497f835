// Size and shape figures of a tet mesh, for `ccm mesh info`: extent, volume, the range of
// dihedral angles and the smallest characteristic length h_e, the length the explicit solver's
// stable step is made of (dt = h_e / c_d, engine/element/tet4.hpp).
#pragma once

#include "engine/core/types.hpp"
#include "engine/mesh/tet_mesh.hpp"

namespace ccm {

struct MeshQuality {
  Vec3 box_min = Vec3::Zero(), box_max = Vec3::Zero();  // of the nodes
  double volume = 0;                                    // sum of the tets' signed volumes
  double min_dihedral_deg = 0, max_dihedral_deg = 0;    // over all six edges of every tet
  int min_dihedral_tet = -1, max_dihedral_tet = -1;     // index of the tet where each occurs
  double min_h = 0;                                     // smallest h_e
  int min_h_tet = -1;
};

// The dihedral angle [deg] of the tet (a, b, c, d) at edge a-b: the angle between the faces
// a-b-c and a-b-d, measured in the plane normal to the edge.
double dihedral_angle_deg(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// Requires at least one tet; tets should have positive volume (a reader's guarantee).
MeshQuality mesh_quality(const TetMesh& mesh);

}  // namespace ccm
