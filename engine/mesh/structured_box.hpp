// A structured tetrahedral mesh of a box: nx x ny x nz hexahedral cells, each split into six
// tets around its main diagonal (Kuhn triangulation, conforming across cells). Used for
// benchmarks and tests that need a mesh independent of Gmsh and exactly reproducible.
#pragma once

#include "engine/mesh/tet_mesh.hpp"

namespace ccm {

// Box [0, size] with the given cell counts (each >= 1). Node (i, j, k) has index
// i + (nx+1) (j + (ny+1) k).
TetMesh structured_box(const Vec3& size, int nx, int ny, int nz);

}  // namespace ccm
