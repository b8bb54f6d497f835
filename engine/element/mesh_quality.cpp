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
  std::vector<TetQuality> all(mesh.tets.size());
  for (size_t e = 0; e < mesh.tets.size(); ++e) {
    const Tet& t = mesh.tets[e];
    TetQuality& tq = all[e];
    tq.tet = static_cast<int>(e);
    tq.min_dihedral_deg = std::numeric_limits<double>::infinity();
    tq.max_dihedral_deg = -tq.min_dihedral_deg;
    for (const auto& edge : kEdges) {
      const double angle =
          dihedral_angle_deg(x[t[edge[0]]], x[t[edge[1]]], x[t[edge[2]]], x[t[edge[3]]]);
      tq.min_dihedral_deg = std::min(tq.min_dihedral_deg, angle);
      tq.max_dihedral_deg = std::max(tq.max_dihedral_deg, angle);
    }
    if (tq.min_dihedral_deg < q.min_dihedral_deg)
      q.min_dihedral_deg = tq.min_dihedral_deg, q.min_dihedral_tet = int(e);
    if (tq.max_dihedral_deg > q.max_dihedral_deg)
      q.max_dihedral_deg = tq.max_dihedral_deg, q.max_dihedral_tet = int(e);
    tq.h = characteristic_length(edge_matrix(x[t[0]], x[t[1]], x[t[2]], x[t[3]]));
    if (tq.h < q.min_h) q.min_h = tq.h, q.min_h_tet = static_cast<int>(e);
  }
  // Smallest h_e first, ties by tet index (deterministic).
  const auto by_h = [](const TetQuality& a, const TetQuality& b) {
    return a.h != b.h ? a.h < b.h : a.tet < b.tet;
  };
  const size_t n_worst = std::min(kWorstListed, all.size());
  q.worst.resize(n_worst);
  std::partial_sort_copy(all.begin(), all.end(), q.worst.begin(), q.worst.end(), by_h);
  const auto middle = all.begin() + static_cast<std::ptrdiff_t>(all.size() / 2);
  std::nth_element(all.begin(), middle, all.end(), by_h);
  q.median_h = middle->h;
  return q;
}

}  // namespace ccm
