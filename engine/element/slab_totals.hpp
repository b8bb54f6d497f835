// What one slab of the element loop reports to add_internal_forces (internal_force.hpp); slabs
// are combined in slab order, so the result does not depend on which thread ran which slab.
#pragma once

#include <limits>

namespace ccm {

struct SlabTotals {
  double max_y = 0.0;  // the largest rho / dt_e^2 of the slab's elements (sets the stable step)
  double min_J = std::numeric_limits<double>::infinity();  // over the elements with J > 0
  int first_bad = -1;  // lowest-numbered element with J <= 0 or non-finite J, else -1
  double bad_J = 0.0;  // its J
  double energy = 0.0;
};

}  // namespace ccm
