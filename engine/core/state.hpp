// The global nodal state of an explicit run, structure-of-arrays, contiguous.
#pragma once

#include <vector>

#include "engine/core/types.hpp"

namespace ccm {

struct State {
  double t = 0.0;
  std::vector<Vec3> X;  // reference positions
  std::vector<Vec3> x;  // current positions (u = x - X)
  std::vector<Vec3> v;  // velocities
  std::vector<Vec3> a;  // accelerations
  std::vector<Vec3> f;  // total nodal force of the last evaluation (scratch)
  std::vector<double> m_lumped;
  std::vector<double> inv_m;

  int n_nodes() const { return static_cast<int>(x.size()); }
};

}  // namespace ccm
