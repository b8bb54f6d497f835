// From a GridSpec to the list of grid points to run, in a deterministic order.
#pragma once

#include <vector>

#include "records/grid_point.hpp"
#include "study/grid/grid_spec.hpp"

namespace ccm::study {

// Every combination of the axes, row-major: ER outermost, then RLS, then KE, then the other
// axes in name order (innermost last); values in the order the file gives them. Indices 0..n-1.
// A grid over a scene: every combination of its axes and levels (named as kTemplateAxisPrefix,
// kTemplateLevelPrefix say, in name order), ER, RLS and KE left at their defaults until the
// run layer derives them from each point's scene (run/template/template_points.hpp).
std::vector<GridPoint> expand_grid(const GridSpec& spec);

// The convergence runs: each [convergence] point at each mesh scale (other_axes["mesh_scale"]),
// points in file order, scales innermost. Indices continue after the main grid's, so every run
// of a grid file has its own index.
std::vector<GridPoint> expand_convergence(const GridSpec& spec);

// Number of points expand_grid returns (the product of the axis lengths).
long grid_size(const GridSpec& spec);

}  // namespace ccm::study
