#include "engine/contact/dcr/edge_orientation.hpp"

#include <algorithm>
#include <cmath>

namespace ccm::dcr {

EdgeOrientation::EdgeOrientation(const SurfaceFeatures& f)
    : faces_(f.edges.size(), std::array<int, 2>{-1, -1}) {
  for (size_t k = 0; k < f.faces.size(); ++k) {
    const Triangle& t = f.faces[k];
    for (int i = 0; i < 3; ++i) {
      std::array<int, 2> e{t[i], t[(i + 1) % 3]};
      if (e[0] > e[1]) std::swap(e[0], e[1]);
      const auto it = std::lower_bound(f.edges.begin(), f.edges.end(), e);
      if (it == f.edges.end() || *it != e) continue;
      auto& slot = faces_[static_cast<size_t>(it - f.edges.begin())];
      (slot[0] < 0 ? slot[0] : slot[1]) = static_cast<int>(k);
    }
  }
}

// Sum of the unit outward normals of the edge's faces at x.
Vec3 EdgeOrientation::outward(const SurfaceFeatures& f, int edge,
                              const std::vector<Vec3>& x) const {
  Vec3 N = Vec3::Zero();
  for (int k : faces_[static_cast<size_t>(edge)]) {
    if (k < 0) continue;
    const Triangle& t = f.faces[static_cast<size_t>(k)];
    const Vec3 n = (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]);
    if (n.norm() > 0.0) N += n.normalized();
  }
  return N;
}

double EdgeOrientation::sign(const SurfaceFeatures& f, int edge_a, int edge_b,
                             const std::vector<Vec3>& x0, double separation) const {
  const auto& ea = f.edges[static_cast<size_t>(edge_a)];
  const auto& eb = f.edges[static_cast<size_t>(edge_b)];
  const Vec3 n = (x0[ea[1]] - x0[ea[0]]).cross(x0[eb[1]] - x0[eb[0]]);
  const double V6 = n.dot(x0[eb[0]] - x0[ea[0]]);  // 6 V
  const double start_sign = V6 >= 0.0 ? 1.0 : -1.0;
  const double n_norm = n.norm();
  if (!(n_norm > 0.0) || std::abs(V6) >= separation * n_norm) return start_sign;
  const Vec3 N = outward(f, edge_a, x0) - outward(f, edge_b, x0);
  const double along = n.dot(N);
  if (!(std::abs(along) >= kMinAlignment * n_norm * N.norm())) return start_sign;
  return along > 0.0 ? 1.0 : -1.0;
}

}  // namespace ccm::dcr
