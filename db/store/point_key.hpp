// Content hash of a grid point: the key for "is this point already done?" across restarts,
// independent of the point's position in the grid file.
#pragma once

#include <string>

#include "records/grid_point.hpp"

namespace ccm::db {

// Canonical text of the point's parameters (ER, RLS, KE and the other axes by name, each in
// shortest round-trip form), hashed with 64-bit FNV-1a; 16 hex digits. The index is left out.
std::string grid_point_hash(const study::GridPoint& point);

// Other axes as "name=value;name=value" (sorted by name), as stored in grid_points.other_axes.
std::string other_axes_text(const study::GridPoint& point);

}  // namespace ccm::db
