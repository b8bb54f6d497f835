// Two-body contact set-ups the contact tests share.
#pragma once

#include "engine/mesh/structured_box.hpp"
#include "engine/solver/explicit_integrator.hpp"

namespace ccm::test {

// Translates a mesh's nodes.
inline TetMesh translated(TetMesh m, const Vec3& by) {
  for (Vec3& x : m.nodes) x += by;
  return m;
}

// Mass-weighted mean velocity of a body.
inline Vec3 mean_velocity(const State& s, const Body& b) {
  Vec3 p = Vec3::Zero();
  double m = 0.0;
  for (int n = b.first_node; n < b.first_node + b.n_nodes; ++n) {
    p += s.m_lumped[static_cast<size_t>(n)] * s.v[static_cast<size_t>(n)];
    m += s.m_lumped[static_cast<size_t>(n)];
  }
  return p / m;
}

}  // namespace ccm::test
