// A mesh's tets and nodes in a spatial order (docs/parallel.md, "The mesh's order"): the tets
// sorted along a Morton (Z-order) curve through their centroids, the nodes numbered by their
// first use in that order. A mesher or a file lists them in whatever order it built them (Gmsh's
// interior nodes follow its Delaunay insertions); the element step then gathers each tet's nodes
// from all over memory. In spatial order it reads them from a few cache lines: on a 200k-tet
// Gmsh plate, 22-25 -> 15 ns per element-step on one thread
// (bench/results/session22-2026-12-07.md), the structured box's figure.
#pragma once

#include "engine/mesh/tet_mesh.hpp"

namespace ccm {

// The same mesh (the same tets, nodes, named surfaces and node sets, regions) renumbered in
// spatial order. Ties on the curve keep the given order, so the result depends only on the mesh.
TetMesh in_locality_order(TetMesh mesh);

}  // namespace ccm
