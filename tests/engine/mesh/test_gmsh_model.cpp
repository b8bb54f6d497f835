// mesh_gmsh_model (engine/mesh/gmsh_mesher.hpp): a caller-built Gmsh model of two volumes
// fragmented into one conforming mesh comes back with a region per tet and the named surfaces.

#include <catch2/catch.hpp>
#include <set>

#include "engine/mesh/gmsh_api.hpp"
#include "engine/mesh/gmsh_mesher.hpp"

using ccm::MeshError;
using ccm::TetMesh;
namespace gmsh = ccm::gmsh;

namespace {

double tet_volume(const TetMesh& m, const ccm::Tet& t) {
  const auto& x = m.nodes;
  return (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).dot(x[t[3]] - x[t[0]]) / 6.0;
}

// Two unit-wide boxes side by side along x (lengths 1 and 2), fragmented so that they share
// their interface, with regions "left" and "right" and the far face of "right" named "end".
void two_boxes() {
  namespace occ = gmsh::model::occ;
  const int left = occ::addBox(0, 0, 0, 1, 1, 1);
  const int right = occ::addBox(1, 0, 0, 2, 1, 1);
  gmsh::vectorpair out;
  std::vector<gmsh::vectorpair> map;
  occ::fragment({{3, left}}, {{3, right}}, out, map);
  occ::synchronize();
  gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, {map[0][0].second}), "left");
  gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, {map[1][0].second}), "right");
  gmsh::vectorpair faces;
  gmsh::model::getEntitiesInBoundingBox(2.99, -0.01, -0.01, 3.01, 1.01, 1.01, faces, 2);
  REQUIRE(faces.size() == 1);
  gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {faces[0].second}), "end");
  gmsh::option::setNumber("Mesh.MeshSizeMax", 0.4);
  gmsh::option::setNumber("Mesh.Algorithm3D", 1);
  gmsh::model::mesh::generate(3);
}

}  // namespace

TEST_CASE("mesh_gmsh_model: regions of a fragmented two-volume model", "[gmsh]") {
  const TetMesh m = ccm::mesh_gmsh_model("two boxes", two_boxes);
  REQUIRE(m.region_names == std::vector<std::string>{"left", "right"});
  REQUIRE(m.tet_region.size() == m.tets.size());
  double volume[2] = {0.0, 0.0};
  std::set<int> nodes_of[2];
  for (size_t e = 0; e < m.tets.size(); ++e) {
    const int r = m.tet_region[e];
    REQUIRE((r == 0 || r == 1));
    const double v = tet_volume(m, m.tets[e]);
    CHECK(v > 0.0);
    volume[r] += v;
    nodes_of[r].insert(m.tets[e].begin(), m.tets[e].end());
  }
  // Flat faces only: the meshed volumes are exact to round-off.
  CHECK(volume[0] == Approx(1.0).epsilon(1e-12));
  CHECK(volume[1] == Approx(2.0).epsilon(1e-12));
  // Conforming: the two regions share the nodes of their interface x = 1, and only those.
  int shared = 0;
  for (int n : nodes_of[0])
    if (nodes_of[1].count(n)) {
      ++shared;
      CHECK(m.nodes[static_cast<size_t>(n)].x() == Approx(1.0).margin(1e-12));
    }
  CHECK(shared >= 4);
  REQUIRE(m.named_surfaces.count("end") == 1);
  for (const auto& tri : m.named_surfaces.at("end"))
    for (int n : tri) CHECK(m.nodes[static_cast<size_t>(n)].x() == Approx(3.0).margin(1e-12));
}

TEST_CASE("mesh_gmsh_model: a model without a mesh is refused", "[gmsh]") {
  CHECK_THROWS_WITH(ccm::mesh_gmsh_model("empty", [] {}),
                    Catch::Contains("empty") && Catch::Contains("no linear tetrahedra"));
}
