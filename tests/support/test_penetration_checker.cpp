#include <catch2/catch.hpp>
#include <vector>

#include "engine/mesh/structured_box.hpp"
#include "tests/support/penetration_checker.hpp"

using ccm::ModelMesh;
using ccm::Vec3;
using ccm::test::nodes_inside_foreign_tets;

namespace {

const ccm::MaterialParams kRubber{ccm::MaterialModel::neo_hookean, 1e6, 0.45, 1000};

// Box "a" on [0, 1]^3 and box "b" above it with a gap (gap 0: the faces coincide), shifted
// sideways by `shift`.
ModelMesh stacked_boxes(double gap, const Vec3& shift = Vec3::Zero()) {
  ModelMesh mesh;
  ccm::add_body(mesh, "a", kRubber, ccm::structured_box(Vec3(1, 1, 1), 3, 3, 3));
  ccm::TetMesh b = ccm::structured_box(Vec3(1, 1, 1), 2, 2, 2);
  for (auto& x : b.nodes) x += shift + Vec3(0, 0, 1 + gap);
  ccm::add_body(mesh, "b", kRubber, b);
  return mesh;
}

// The index of the node of `body` nearest to p.
int nearest_node(const ModelMesh& mesh, int body, const Vec3& p) {
  const auto& b = mesh.bodies[static_cast<size_t>(body)];
  int best = b.first_node;
  for (int n = b.first_node; n < b.first_node + b.n_nodes; ++n)
    if ((mesh.X[static_cast<size_t>(n)] - p).norm() <
        (mesh.X[static_cast<size_t>(best)] - p).norm())
      best = n;
  return best;
}

}  // namespace

TEST_CASE("penetration checker: separated and touching boxes have no penetration", "[dcr]") {
  for (double gap : {0.1, 0.0}) {
    CAPTURE(gap);
    const ModelMesh mesh = stacked_boxes(gap);
    CHECK(nodes_inside_foreign_tets(mesh, mesh.X, 1e-9).empty());
  }
}

TEST_CASE("penetration checker: a node pushed into the other body is found", "[dcr]") {
  const ModelMesh mesh = stacked_boxes(0.0);
  std::vector<Vec3> x = mesh.X;
  // The bottom-centre node of b, pushed 0.1 down into a.
  const int node = nearest_node(mesh, 1, Vec3(0.5, 0.5, 1.0));
  x[static_cast<size_t>(node)].z() -= 0.1;
  // ... nudged off a's grid planes so that it lies strictly inside one tet.
  x[static_cast<size_t>(node)] += Vec3(0.011, 0.007, 0);
  const auto found = nodes_inside_foreign_tets(mesh, x, 1e-9);
  // The node is inside one tet of a; b's bulged bottom tets now also hold some of a's top nodes.
  int hits_of_node = 0;
  for (const auto& [n, e] : found) {
    const int node_body = n < mesh.bodies[1].first_node ? 0 : 1;
    CHECK(mesh.element_body[static_cast<size_t>(e)] != node_body);
    if (n == node) ++hits_of_node;
    if (n != node) CHECK(mesh.X[static_cast<size_t>(n)].z() == Approx(1.0));
  }
  CHECK(hits_of_node == 1);
  // Pushed only a hair (less than the tolerance in barycentric terms): not reported.
  x[static_cast<size_t>(node)].z() = 1.0 - 1e-13;
  CHECK(nodes_inside_foreign_tets(mesh, x, 1e-9).empty());
}

TEST_CASE("penetration checker: overlapping boxes report every buried node", "[dcr]") {
  // b's lower half inside a, shifted off a's grid planes so that no node lies on a tet face.
  const Vec3 shift(0.031, 0.017, 0.023);
  const ModelMesh mesh = stacked_boxes(-0.5, shift);
  const auto found = nodes_inside_foreign_tets(mesh, mesh.X, 1e-9);

  // Expected: the nodes of each box strictly inside the other box.
  auto strictly_in = [](const Vec3& p, const Vec3& lo, const Vec3& hi) {
    return (p.array() > lo.array() + 1e-9).all() && (p.array() < hi.array() - 1e-9).all();
  };
  std::vector<int> expected;
  for (int n = 0; n < mesh.n_nodes(); ++n) {
    const Vec3& p = mesh.X[static_cast<size_t>(n)];
    const bool in_a = strictly_in(p, Vec3(0, 0, 0), Vec3(1, 1, 1));
    const bool in_b = strictly_in(p, shift + Vec3(0, 0, 0.5), shift + Vec3(1, 1, 1.5));
    if (n < mesh.bodies[1].first_node ? in_b : in_a) expected.push_back(n);
  }
  std::vector<int> nodes;
  for (const auto& [n, e] : found) {
    CHECK(mesh.element_body[static_cast<size_t>(e)] != (n < mesh.bodies[1].first_node ? 0 : 1));
    if (nodes.empty() || nodes.back() != n) nodes.push_back(n);
  }
  CHECK(expected.size() >= 5);
  CHECK(nodes == expected);
  // Each buried node is strictly inside exactly one tet.
  CHECK(found.size() == nodes.size());
}
