// An independent, brute-force penetration check for contact tests: shares no code with the DCR
// contact search, so each can catch the other's mistakes.
#pragma once

#include <span>
#include <utility>
#include <vector>

#include "engine/mesh/model_mesh.hpp"

namespace ccm::test {

// Every (node, element) such that the node lies strictly inside tet `element` at positions x
// (all four barycentric coordinates > tol) and is not one of its vertices. Sorted by (node,
// element). Tets of (near-)zero volume are skipped. O(n_nodes * n_tets) in the worst case; nodes
// are sorted by x so each tet only looks at the nodes within its bounding box's x range.
std::vector<std::pair<int, int>> nodes_inside_foreign_tets(const ModelMesh& mesh,
                                                           std::span<const Vec3> x, double tol);

}  // namespace ccm::test
