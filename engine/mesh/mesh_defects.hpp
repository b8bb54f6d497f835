// Defects that make a mesh file impossible to simulate as it stands, found alike for every format
// (docs/meshes.md, "What is refused"). A reader refuses each with the file, the element or node
// label and the message built here:
//   - tets of both orientations: the minority is inverted (tangled, or numbered the wrong way);
//     a file whose tets are all of one orientation is read in that convention;
//   - nodes on no tet (a reference node, a shell or beam part): no mass, no stiffness;
//   - two nodes at one position inside one region: the tets on either side are not connected,
//     a cut the body would open along.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/mesh/tet_mesh.hpp"

namespace ccm {

// The indices, ascending, of the tets whose signed volume has the sign fewer tets have (the
// negative ones on a tie); empty when every tet has one sign.
std::vector<std::size_t> inverted_minority(std::span<const double> six_volumes);

// "element 12 is inverted: ..." for the inverted tets' labels (ascending, at least one) among
// n_tets; `element` is the format's word ("element", "tetrahedron").
std::string inverted_problem(std::span<const long> labels, std::size_t n_tets,
                             const std::string& element);

// "node 6 belongs to no tetrahedron ..." for the unused nodes' labels (at least one).
std::string unused_nodes_problem(std::span<const long> labels, std::size_t file_nodes);

struct CoincidentNodes {
  std::size_t count = 0;        // nodes that share their position with an earlier one in one region
  int first = -1, second = -1;  // the first such pair (indices into the mesh's nodes)
};

// Nodes at exactly one position, both on tets of one region (any two when the mesh has no
// regions): coincident nodes in different regions are parts that meet, and are allowed.
CoincidentNodes coincident_nodes(const TetMesh& mesh);

std::string coincident_problem(long label_a, long label_b, const Vec3& at, std::size_t count);

}  // namespace ccm
