#include "tests/support/penetration_checker.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ccm::test {

std::vector<std::pair<int, int>> nodes_inside_foreign_tets(const ModelMesh& mesh,
                                                           std::span<const Vec3> x, double tol) {
  if (static_cast<int>(x.size()) < mesh.n_nodes())
    throw std::invalid_argument("nodes_inside_foreign_tets: fewer positions than nodes");

  // Nodes ordered by their x coordinate, for a binary search per tet.
  std::vector<int> order(static_cast<size_t>(mesh.n_nodes()));
  for (int i = 0; i < mesh.n_nodes(); ++i) order[static_cast<size_t>(i)] = i;
  std::sort(order.begin(), order.end(),
            [&](int i, int j) { return x[i].x() < x[j].x() || (x[i].x() == x[j].x() && i < j); });
  std::vector<double> sorted_x(order.size());
  for (size_t k = 0; k < order.size(); ++k) sorted_x[k] = x[order[k]].x();

  std::vector<std::pair<int, int>> found;
  for (int e = 0; e < mesh.n_elements(); ++e) {
    const Tet& t = mesh.tets[static_cast<size_t>(e)];
    const Vec3 &x0 = x[t[0]], &x1 = x[t[1]], &x2 = x[t[2]], &x3 = x[t[3]];
    // Six times the signed volume, and the scale below which the tet counts as flat.
    const double v6 = (x1 - x0).dot((x2 - x0).cross(x3 - x0));
    const double edge = std::max({(x1 - x0).norm(), (x2 - x0).norm(), (x3 - x0).norm()});
    if (!(std::abs(v6) > 1e-14 * edge * edge * edge)) continue;

    const Vec3 lo = x0.cwiseMin(x1).cwiseMin(x2).cwiseMin(x3);
    const Vec3 hi = x0.cwiseMax(x1).cwiseMax(x2).cwiseMax(x3);
    const auto first = std::lower_bound(sorted_x.begin(), sorted_x.end(), lo.x());
    const auto last = std::upper_bound(sorted_x.begin(), sorted_x.end(), hi.x());
    for (auto it = first; it != last; ++it) {
      const int n = order[static_cast<size_t>(it - sorted_x.begin())];
      const Vec3& p = x[n];
      if (p.y() < lo.y() || p.y() > hi.y() || p.z() < lo.z() || p.z() > hi.z()) continue;
      if (n == t[0] || n == t[1] || n == t[2] || n == t[3]) continue;
      // Barycentric coordinates: the volume of the tet with vertex i replaced by p, over v6.
      const double l0 = (x1 - p).dot((x2 - p).cross(x3 - p)) / v6;
      const double l1 = (p - x0).dot((x2 - x0).cross(x3 - x0)) / v6;
      const double l2 = (x1 - x0).dot((p - x0).cross(x3 - x0)) / v6;
      const double l3 = (x1 - x0).dot((x2 - x0).cross(p - x0)) / v6;
      if (l0 > tol && l1 > tol && l2 > tol && l3 > tol) found.emplace_back(n, e);
    }
  }
  std::sort(found.begin(), found.end());
  return found;
}

}  // namespace ccm::test
