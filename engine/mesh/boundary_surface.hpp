// Boundary surface of a tetrahedral element set: the faces that belong to exactly one tet,
// oriented so that their normal points out of the body.
#pragma once

#include <span>
#include <vector>

#include "engine/mesh/tet_mesh.hpp"

namespace ccm {

// Each returned triangle (a, b, c) has (x_b - x_a) x (x_c - x_a) pointing outward, given that
// every tet has positive signed volume. Deterministic order: by the owning tet, then local face.
std::vector<Triangle> extract_boundary(std::span<const Tet> tets);

// For each triangle, the index into `tets` of the tet that has it as a face (its three nodes
// in any order), or -1 when none does. A boundary triangle has exactly one such tet; for a face
// shared by two tets the first in `tets` is returned.
std::vector<int> owning_tets(std::span<const Tet> tets, std::span<const Triangle> triangles);

// Outward unit normal and area of a triangle at positions x.
Vec3 triangle_normal(const Triangle& t, std::span<const Vec3> x);
double triangle_area(const Triangle& t, std::span<const Vec3> x);

// Each node's share of a surface's area: a third of every triangle it belongs to, over the total
// (nodes ascending, shares summing to 1); the weights that spread a force over a surface.
struct AreaShares {
  std::vector<int> nodes;
  std::vector<double> share;
  double area = 0.0;  // m^2, the surface's total
};
AreaShares area_shares(const std::vector<Triangle>& surface, const std::vector<Vec3>& X);

}  // namespace ccm
