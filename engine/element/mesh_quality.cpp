#include "engine/element/mesh_quality.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "engine/element/tet4.hpp"

namespace ccm {

double dihedral_angle_deg(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 u = (b - a).normalized();
  const Vec3 to_c = (c - a) - (c - a).dot(u) * u;  // components normal to the edge
  const Vec3 to_d = (d - a) - (d - a).dot(u) * u;
  const double cosine = to_c.dot(to_d) / (to_c.norm() * to_d.norm());
  return std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

MeshQuality mesh_quality(const TetMesh& mesh) {
  MeshQuality q;
  const auto& x = mesh.nodes;
  q.box_min = Vec3::Constant(std::numeric_limits<double>::infinity());
  q.box_max = -q.box_min;
  for (const Vec3& p : x) {
    q.box_min = q.box_min.cwiseMin(p);
    q.box_max = q.box_max.cwiseMax(p);
  }
  q.volume = mesh_volume(mesh);
  q.min_dihedral_deg = q.min_h = std::numeric_limits<double>::infinity();
  q.max_dihedral_deg = -q.min_dihedral_deg;
  // The six edges (a, b) of a tet with the two other nodes (c, d).
  static constexpr int kEdges[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                                       {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
  for (size_t e = 0; e < mesh.tets.size(); ++e) {
    const Tet& t = mesh.tets[e];
    for (const auto& edge : kEdges) {
      const double angle =
          dihedral_angle_deg(x[t[edge[0]]], x[t[edge[1]]], x[t[edge[2]]], x[t[edge[3]]]);
      if (angle < q.min_dihedral_deg) q.min_dihedral_deg = angle, q.min_dihedral_tet = int(e);
      if (angle > q.max_dihedral_deg) q.max_dihedral_deg = angle, q.max_dihedral_tet = int(e);
    }
    const double h = characteristic_length(edge_matrix(x[t[0]], x[t[1]], x[t[2]], x[t[3]]));
    if (h < q.min_h) q.min_h = h, q.min_h_tet = static_cast<int>(e);
  }
  return q;
}

}  // namespace ccm
