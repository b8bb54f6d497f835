// The nodal quantities of the averaged-nodal-pressure tet (nodal_pressure.hpp;
// docs/elements.md): one entry per node of the whole mesh, meaningful at the nodes of the blocks
// that use that element and empty when none does.
#pragma once

#include <vector>

#include "engine/element/padded_nodes.hpp"

namespace ccm {

struct NodalPressureData {
  // V0_n = sum_{e containing n} V0_e / 4, the reference volume a node represents (eq. NP.1).
  std::vector<double> V0;
  // Scratch of the current evaluation, rewritten by every call of add_internal_forces (so a Model
  // is run by one run at a time, as every caller does): the current nodal volume V_n, each node's
  // current position with its pressure p_n (eq. NP.2-NP.3) in the fourth slot (x, y, z, p_n), so
  // the element pass loads both in one move, and per block the largest |ln J_n| of its nodes,
  // which sets the stable step (eq. NP.6). While the volumes are summed (pass 1) the fourth slot
  // holds the partial V_n: one node per 32 bytes, as the forces, so threads seldom share a line.
  mutable std::vector<double> V;
  mutable PaddedNodes position_pressure;
  mutable std::vector<double> max_abs_log_J;
  bool empty() const { return V0.empty(); }
};

}  // namespace ccm
