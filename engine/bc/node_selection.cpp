#include "engine/bc/node_selection.hpp"

#include <cmath>
#include <limits>

namespace ccm {
namespace {

struct NodeRange {
  int begin;
  int end;
};

NodeRange range_of(const ModelMesh& mesh, int body) {
  if (body < 0) return {0, mesh.n_nodes()};
  const Body& b = mesh.bodies[static_cast<size_t>(body)];
  return {b.first_node, b.first_node + b.n_nodes};
}

double plane_distance(const Vec3& x, const Vec3& point, const Vec3& unit_normal) {
  return std::abs((x - point).dot(unit_normal));
}

}  // namespace

std::vector<int> nodes_in_box(const ModelMesh& mesh, int body, const Vec3& lo, const Vec3& hi) {
  std::vector<int> out;
  const NodeRange r = range_of(mesh, body);
  for (int n = r.begin; n < r.end; ++n) {
    const Vec3& X = mesh.X[static_cast<size_t>(n)];
    if ((X.array() >= lo.array()).all() && (X.array() <= hi.array()).all()) out.push_back(n);
  }
  return out;
}

std::vector<int> nodes_on_plane(const ModelMesh& mesh, int body, const Vec3& point,
                                const Vec3& normal, double tolerance) {
  std::vector<int> out;
  const Vec3 n = normal.normalized();
  const NodeRange r = range_of(mesh, body);
  for (int i = r.begin; i < r.end; ++i)
    if (plane_distance(mesh.X[static_cast<size_t>(i)], point, n) <= tolerance) out.push_back(i);
  return out;
}

std::vector<Triangle> boundary_on_plane(const ModelMesh& mesh, int body, const Vec3& point,
                                        const Vec3& normal, double tolerance) {
  std::vector<Triangle> out;
  const Vec3 n = normal.normalized();
  for (const Triangle& t : mesh.bodies[static_cast<size_t>(body)].boundary) {
    bool on = true;
    for (int v : t)
      on = on && plane_distance(mesh.X[static_cast<size_t>(v)], point, n) <= tolerance;
    if (on) out.push_back(t);
  }
  return out;
}

int nearest_node(const ModelMesh& mesh, int body, const Vec3& p) {
  const NodeRange r = range_of(mesh, body);
  int best = -1;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (int i = r.begin; i < r.end; ++i) {
    const double d2 = (mesh.X[static_cast<size_t>(i)] - p).squaredNorm();
    if (d2 < best_d2) {
      best_d2 = d2;
      best = i;
    }
  }
  return best;
}

}  // namespace ccm
