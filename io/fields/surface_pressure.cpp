#include "io/fields/surface_pressure.hpp"

#include <unordered_map>

#include "engine/mesh/boundary_surface.hpp"

namespace ccm::fields {

std::vector<double> face_contact_pressure(std::span<const Triangle> faces, std::span<const Vec3> x,
                                          std::span<const Vec3> force,
                                          std::vector<Vec3>* traction) {
  std::unordered_map<int, double> node_area;  // A_i
  std::vector<double> area(faces.size());
  for (size_t f = 0; f < faces.size(); ++f) {
    area[f] = triangle_area(faces[f], x);
    for (int i : faces[f]) node_area[i] += area[f] / 3.0;
  }
  std::vector<double> pressure(faces.size(), 0.0);
  if (traction) traction->assign(faces.size(), Vec3::Zero());
  for (size_t f = 0; f < faces.size(); ++f) {
    Vec3 t = Vec3::Zero();
    for (int i : faces[f]) {
      const double a = node_area[i];
      if (a > 0.0) t += force[static_cast<size_t>(i)] / a;
    }
    t /= 3.0;
    if (area[f] > 0.0) pressure[f] = -t.dot(triangle_normal(faces[f], x));
    if (traction) (*traction)[f] = t;
  }
  return pressure;
}

}  // namespace ccm::fields
