// From a GridSpec to the list of grid points to run, in a deterministic order.
#pragma once

#include <vector>

#include "records/grid_point.hpp"
#include "study/grid/grid_spec.hpp"

namespace ccm::study {

// Every combination of the axes, row-major: ER outermost, then RLS, then KE, then the other
// axes in name order (innermost last); values in the order the file gives them. Indices 0..n-1.
std::vector<GridPoint> expand_grid(const GridSpec& spec);

// The convergence runs: each [convergence] point at each mesh scale (other_axes["mesh_scale"]),
// points in file order, scales innermost. Indices continue after the main grid's, so every run
// of a grid file has its own index.
std::vector<GridPoint> expand_convergence(const GridSpec& spec);

// Number of points expand_grid returns (the product of the axis lengths).
long grid_size(const GridSpec& spec);

}  // namespace ccm::study
