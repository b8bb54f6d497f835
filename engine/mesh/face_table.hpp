// Which tet a triangle bounds: tet faces keyed by their sorted node triple, with the node opposite,
// so that a named triangle of a mesh file can be checked and oriented away from its tet.
#pragma once

#include <array>
#include <utility>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/mesh/tet_mesh.hpp"

namespace ccm {

class FaceTable {
 public:
  // Only faces whose three nodes all have keep[node] != 0 are listed, which keeps the table small.
  FaceTable(const std::vector<Tet>& tets, const std::vector<char>& keep);
  // The node opposite the face in the first tet (lowest index) that has it, or -1.
  int opposite_node(std::array<int, 3> face) const;

 private:
  std::vector<std::pair<std::array<int, 3>, int>> faces_;  // sorted by face
};

// The triangle with its node order chosen so that its normal (x1 - x0) x (x2 - x0) points away
// from node `opposite`.
Triangle oriented_away_from(Triangle t, int opposite, const std::vector<Vec3>& x);

}  // namespace ccm
