#include "engine/bc/boundary_conditions.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "engine/mesh/boundary_surface.hpp"

namespace ccm {

void SurfaceLoad::add_to(std::span<Vec3> f, double t) const {
  const Vec3 F = magnitude(t) * direction;
  for (size_t i = 0; i < nodes.size(); ++i) f[static_cast<size_t>(nodes[i])] += area_share[i] * F;
}

SurfaceLoad make_surface_load(const std::string& name, const ModelMesh& mesh,
                              const std::vector<Triangle>& surface, const Vec3& direction,
                              TimeTable magnitude) {
  std::map<int, double> share;
  double total = 0.0;
  for (const Triangle& t : surface) {
    const double A = triangle_area(t, mesh.X);
    total += A;
    for (int n : t) share[n] += A / 3.0;
  }
  if (!(total > 0.0)) throw std::invalid_argument("surface load '" + name + "' has no area");
  SurfaceLoad load{name, {}, {}, direction.normalized(), std::move(magnitude)};
  for (const auto& [node, a] : share) {
    load.nodes.push_back(node);
    load.area_share.push_back(a / total);
  }
  return load;
}

void BoundaryConditions::fix(const std::vector<int>& nodes) {
  fixed_nodes.insert(fixed_nodes.end(), nodes.begin(), nodes.end());
  std::sort(fixed_nodes.begin(), fixed_nodes.end());
  fixed_nodes.erase(std::unique(fixed_nodes.begin(), fixed_nodes.end()), fixed_nodes.end());
}

}  // namespace ccm
