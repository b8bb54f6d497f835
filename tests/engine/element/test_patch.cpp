// Evidence 2: patch test on an unstructured Gmsh tet mesh. A linear displacement field gives the
// same deformation gradient (hence stress) in every element and zero net internal force at every
// interior node.
#include <algorithm>
#include <catch2/catch.hpp>

#include "engine/element/internal_force.hpp"
#include "engine/mesh/gmsh_mesher.hpp"
#include "tests/support/tolerance.hpp"

using namespace ccm;

TEST_CASE("Patch test: uniform stress and zero interior force under a linear field", "[patch]") {
  PrimitiveSpec box{PrimitiveKind::box};
  box.size = Vec3(1.0, 0.7, 0.5);
  box.mesh_size = 0.15;
  ModelMesh mesh;
  add_body(mesh, "patch", {MaterialModel::neo_hookean, 2.0e6, 0.35, 1000.0},
           mesh_primitive(box, Placement{}));
  const ElementSet elements = make_element_set(mesh);
  REQUIRE(elements.n_elements() > 100);

  Mat3 A;  // displacement gradient of u = A X + b: a finite, non-symmetric strain
  A << 0.02, -0.01, 0.005, 0.015, -0.03, 0.01, -0.004, 0.02, 0.025;
  const Vec3 b(0.3, -0.2, 0.1);
  std::vector<Vec3> x(mesh.X.size());
  for (size_t i = 0; i < x.size(); ++i) x[i] = mesh.X[i] + A * mesh.X[i] + b;

  const Mat3 F_expected = Mat3::Identity() + A;
  double worst_F = 0.0;
  for (int e = 0; e < elements.n_elements(); ++e) {
    const Tet& t = elements.tets[static_cast<size_t>(e)];
    const Mat3 F = edge_matrix(x[t[0]], x[t[1]], x[t[2]], x[t[3]]) *
                   elements.reference[static_cast<size_t>(e)].Dm_inv;
    worst_F = std::max(worst_F, test::relative_error(F, F_expected));
  }
  // F (and so P) is the same in every element to round-off: 1e-12 relative (the mesh's
  // Dm^-1 carries ~1e-15 error per entry, amplified by at most the element aspect ratio).
  CHECK(worst_F < 1e-12);

  std::vector<Vec3> f(mesh.X.size(), Vec3::Zero());
  add_internal_forces(elements, x, f);
  const std::vector<int>& boundary = mesh.node_sets.at("patch/boundary");
  double max_force = 0.0, max_interior = 0.0;
  int n_interior = 0;
  for (int n = 0; n < mesh.n_nodes(); ++n) {
    const double fn = f[static_cast<size_t>(n)].norm();
    max_force = std::max(max_force, fn);
    if (!std::binary_search(boundary.begin(), boundary.end(), n)) {
      max_interior = std::max(max_interior, fn);
      ++n_interior;
    }
  }
  REQUIRE(n_interior > 10);
  REQUIRE(max_force > 0.0);
  // Interior forces cancel to round-off relative to the boundary forces (issue: 1e-10).
  CHECK(max_interior / max_force < 1e-10);
}
