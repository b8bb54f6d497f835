#include "engine/bc/boundary_conditions.hpp"

#include <algorithm>
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
  AreaShares shares = area_shares(surface, mesh.X);
  if (!(shares.area > 0.0)) throw std::invalid_argument("surface load '" + name + "' has no area");
  return {name, std::move(shares.nodes), std::move(shares.share), direction.normalized(),
          std::move(magnitude)};
}

void BoundaryConditions::fix(const std::vector<int>& nodes) {
  fixed_nodes.insert(fixed_nodes.end(), nodes.begin(), nodes.end());
  std::sort(fixed_nodes.begin(), fixed_nodes.end());
  fixed_nodes.erase(std::unique(fixed_nodes.begin(), fixed_nodes.end()), fixed_nodes.end());
}

}  // namespace ccm
