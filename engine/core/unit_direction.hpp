// A direction given by a user or a scene (an axis, a track, a slide), scaled to unit length.
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

#include "engine/core/types.hpp"

namespace ccm {

// `v / |v|`. Throws std::invalid_argument "<what> must be non-zero and finite" otherwise.
inline Vec3 unit_direction(const Vec3& v, const std::string& what) {
  const double norm = v.norm();
  if (!(norm > 0.0) || !std::isfinite(norm))
    throw std::invalid_argument(what + " must be non-zero and finite");
  return v / norm;
}

}  // namespace ccm
