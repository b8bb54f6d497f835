// Nodal vectors as the element kernel moves them: each node padded to four doubles (x, y, z, 0)
// on a 32-byte boundary, so that one node is one aligned 256-bit load or store (lanes.hpp). The
// integrator keeps the positions in this form beside State::x and takes the internal forces in
// it (engine/solver/explicit_integrator.cpp).
#pragma once

#include <span>
#include <vector>

#include "engine/core/types.hpp"

namespace ccm {

struct alignas(32) PaddedVec3 {
  double v[4] = {0.0, 0.0, 0.0, 0.0};
};

using PaddedNodes = std::vector<PaddedVec3>;

inline PaddedVec3 padded(const Vec3& a) { return {{a.x(), a.y(), a.z(), 0.0}}; }

inline Vec3 unpadded(const PaddedVec3& a) { return {a.v[0], a.v[1], a.v[2]}; }

}  // namespace ccm
