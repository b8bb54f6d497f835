// Boundary conditions of a run: fixed nodes, prescribed surface force histories, gravity.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "engine/core/time_table.hpp"
#include "engine/mesh/model_mesh.hpp"

namespace ccm {

// A total force F(t) = table(t) * direction [N] spread over a surface by area: each node
// receives the share of one third of the area of every triangle it belongs to.
struct SurfaceLoad {
  std::string name;
  std::vector<int> nodes;
  std::vector<double> area_share;  // sums to 1
  Vec3 direction = Vec3::UnitX();  // unit
  TimeTable magnitude;

  // Adds the load at time t into f.
  void add_to(std::span<Vec3> f, double t) const;
};

// Throws std::invalid_argument when the surface has no area.
SurfaceLoad make_surface_load(const std::string& name, const ModelMesh& mesh,
                              const std::vector<Triangle>& surface, const Vec3& direction,
                              TimeTable magnitude);

struct BoundaryConditions {
  std::vector<int> fixed_nodes;  // sorted, unique: u = X fixed, v = a = 0
  std::vector<SurfaceLoad> loads;
  Vec3 gravity = Vec3::Zero();

  bool has_gravity() const { return gravity.squaredNorm() > 0.0; }
  void fix(const std::vector<int>& nodes);  // adds nodes, keeps the list sorted and unique
};

}  // namespace ccm
