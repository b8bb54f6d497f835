// Size and shape figures of a tet mesh, for `ccm mesh info`: extent, volume, the range of
// dihedral angles and the smallest characteristic length h_e, the length the explicit solver's
// stable step is made of (dt = h_e / c_d, engine/element/tet4.hpp).
#pragma once

#include <cstddef>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/mesh/tet_mesh.hpp"

namespace ccm {

// One tet's figures: its characteristic length and its extreme dihedral angles.
struct TetQuality {
  int tet = -1;  // index into the mesh's tets
  double h = 0;  // h_e
  double min_dihedral_deg = 0, max_dihedral_deg = 0;
};

struct MeshQuality {
  Vec3 box_min = Vec3::Zero(), box_max = Vec3::Zero();  // of the nodes
  double volume = 0;                                    // sum of the tets' signed volumes
  double min_dihedral_deg = 0, max_dihedral_deg = 0;    // over all six edges of every tet
  int min_dihedral_tet = -1, max_dihedral_tet = -1;     // index of the tet where each occurs
  double min_h = 0;                                     // smallest h_e
  int min_h_tet = -1;
  double median_h = 0;  // h_e of the median tet
  // The tets of smallest h_e, smallest first (at most kWorstListed): they set the stable step of
  // the whole mesh, dt = safety * min_e h_e / c_d.
  std::vector<TetQuality> worst;
};

inline constexpr std::size_t kWorstListed = 5;

// A tet whose h_e is below this fraction of the median's is nearly degenerate (a sliver): it alone
// shortens the whole mesh's stable step by the same factor.
inline constexpr double kSliverFraction = 0.1;

// The dihedral angle [deg] of the tet (a, b, c, d) at edge a-b: the angle between the faces
// a-b-c and a-b-d, measured in the plane normal to the edge.
double dihedral_angle_deg(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// Requires at least one tet; tets should have positive volume (a reader's guarantee).
MeshQuality mesh_quality(const TetMesh& mesh);

}  // namespace ccm
