#include <algorithm>
#include <catch2/catch.hpp>
#include <map>
#include <set>
#include <stdexcept>

#include "engine/contact/dcr/contact_surface.hpp"
#include "engine/mesh/boundary_surface.hpp"
#include "engine/mesh/structured_box.hpp"

using ccm::ModelMesh;
using ccm::Triangle;
using ccm::Vec3;
using ccm::dcr::make_surface_features;
using ccm::dcr::SurfaceFeatures;

namespace {

const ccm::MaterialParams kRubber{ccm::MaterialModel::neo_hookean, 1e6, 0.45, 1000};

// Two boxes; the second has a named surface "top" (its z = max face), given as a TetMesh
// named surface so that it reaches ModelMesh::surfaces as "upper/top".
ModelMesh two_boxes() {
  ModelMesh mesh;
  ccm::add_body(mesh, "lower", kRubber, ccm::structured_box(Vec3(1, 1, 0.5), 3, 3, 2));
  ccm::TetMesh upper = ccm::structured_box(Vec3(1, 1, 0.5), 2, 2, 1);
  for (auto& n : upper.nodes) n.z() += 0.6;
  for (const Triangle& t : ccm::extract_boundary(upper.tets)) {
    bool top = true;
    for (int n : t) top = top && upper.nodes[static_cast<size_t>(n)].z() > 1.05;
    if (top) upper.named_surfaces["top"].push_back(t);
  }
  ccm::add_body(mesh, "upper", kRubber, upper);
  return mesh;
}

void check_invariants(const SurfaceFeatures& f) {
  REQUIRE(f.node_body.size() == f.nodes.size());
  REQUIRE(f.edge_body.size() == f.edges.size());
  REQUIRE(f.face_body.size() == f.faces.size());
  CHECK(std::is_sorted(f.nodes.begin(), f.nodes.end()));
  CHECK(std::adjacent_find(f.nodes.begin(), f.nodes.end()) == f.nodes.end());
  CHECK(std::is_sorted(f.edges.begin(), f.edges.end()));
  CHECK(std::adjacent_find(f.edges.begin(), f.edges.end()) == f.edges.end());
  for (const auto& e : f.edges) CHECK(e[0] < e[1]);
  // Every side of every face is an edge, every edge a side of some face, every face node a node.
  std::set<std::array<int, 2>> sides;
  for (const Triangle& t : f.faces)
    for (int k = 0; k < 3; ++k) {
      const int a = t[static_cast<size_t>(k)], b = t[static_cast<size_t>((k + 1) % 3)];
      sides.insert({std::min(a, b), std::max(a, b)});
      CHECK(std::binary_search(f.nodes.begin(), f.nodes.end(), a));
    }
  CHECK(sides == std::set<std::array<int, 2>>(f.edges.begin(), f.edges.end()));
}

}  // namespace

TEST_CASE("contact surface: features of two whole boundaries", "[dcr]") {
  const ModelMesh mesh = two_boxes();
  const SurfaceFeatures f = make_surface_features(mesh, {"lower/boundary", "upper/boundary"});
  check_invariants(f);

  const auto& lower = mesh.surfaces.at("lower/boundary");
  const auto& upper = mesh.surfaces.at("upper/boundary");
  CHECK(f.n_faces() == static_cast<int>(lower.triangles.size() + upper.triangles.size()));
  // Faces keep the mesh's order and orientation.
  CHECK(f.faces.front() == lower.triangles.front());
  CHECK(f.faces.back() == upper.triangles.back());

  // Closed surfaces: E = 3F/2 and V - E + F = 2 per body.
  CHECK(2 * f.n_edges() == 3 * f.n_faces());
  CHECK(f.n_nodes() - f.n_edges() + f.n_faces() == 4);
  CHECK(f.nodes == ccm::nodes_of(f.faces));

  // Owners.
  std::map<int, int> faces_per_body, nodes_per_body;
  for (int b : f.face_body) ++faces_per_body[b];
  for (int b : f.node_body) ++nodes_per_body[b];
  CHECK(faces_per_body[0] == static_cast<int>(lower.triangles.size()));
  CHECK(faces_per_body[1] == static_cast<int>(upper.triangles.size()));
  CHECK(nodes_per_body[0] == static_cast<int>(mesh.node_sets.at("lower/boundary").size()));
  CHECK(nodes_per_body[1] == static_cast<int>(mesh.node_sets.at("upper/boundary").size()));
  for (size_t i = 0; i < f.edges.size(); ++i) {
    const int n = f.edges[i][0];
    const int owner = n < mesh.bodies[1].first_node ? 0 : 1;
    CHECK(f.edge_body[i] == owner);
  }
}

TEST_CASE("contact surface: a named part of a boundary, and overlapping lists", "[dcr]") {
  const ModelMesh mesh = two_boxes();
  const auto& top = mesh.surfaces.at("upper/top").triangles;
  REQUIRE(top.size() == 8);  // 2 x 2 cells, two triangles each

  const SurfaceFeatures part = make_surface_features(mesh, {"upper/top"});
  check_invariants(part);
  CHECK(part.faces == top);
  CHECK(part.n_nodes() == 9);
  CHECK(part.n_edges() == 16);  // open 2 x 2 grid: 12 grid lines + 4 diagonals
  for (int b : part.node_body) CHECK(b == 1);

  // The top faces also belong to the boundary: listed twice, kept once.
  const SurfaceFeatures both = make_surface_features(mesh, {"upper/boundary", "upper/top"});
  const SurfaceFeatures boundary = make_surface_features(mesh, {"upper/boundary"});
  check_invariants(both);
  CHECK(both.faces == boundary.faces);
  CHECK(both.edges == boundary.edges);
  CHECK(both.nodes == boundary.nodes);
  // The same surface twice changes nothing either.
  CHECK(make_surface_features(mesh, {"upper/top", "upper/top"}).faces == top);
}

TEST_CASE("contact surface: an unknown surface is named in the error", "[dcr]") {
  const ModelMesh mesh = two_boxes();
  CHECK_THROWS_AS(make_surface_features(mesh, {"lower/boundary", "ball/boundary"}),
                  std::invalid_argument);
  CHECK_THROWS_WITH(make_surface_features(mesh, {"ball/boundary"}),
                    Catch::Contains("ball/boundary"));
  CHECK(make_surface_features(mesh, {}).nodes.empty());
}
