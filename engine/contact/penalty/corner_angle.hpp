// The angle of a triangle at one corner: the weight of a face's normal in an angle-weighted
// pseudo-normal (Baerentzen & Aanaes 2005; surface_distance.hpp).
#pragma once

#include <Eigen/Geometry>
#include <cmath>

#include "engine/core/types.hpp"

namespace ccm {

// The angle at `corner` between the edges to p and q [rad].
inline double corner_angle(const Vec3& corner, const Vec3& p, const Vec3& q) {
  const Vec3 u = (p - corner).normalized(), v = (q - corner).normalized();
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

}  // namespace ccm
