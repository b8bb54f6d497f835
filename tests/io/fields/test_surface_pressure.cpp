// Face contact pressure from nodal forces (io/fields/surface_pressure.hpp) against a closed form
// and the force balance it is built on.
#include <catch2/catch.hpp>
#include <random>

#include "engine/mesh/boundary_surface.hpp"
#include "engine/mesh/structured_box.hpp"
#include "io/fields/surface_pressure.hpp"

using namespace ccm;
using namespace ccm::fields;

namespace surface_pressure_test {

struct TopFace {
  std::vector<Triangle> faces;
  std::vector<Vec3> x;
  std::vector<bool> interior;  // node strictly inside the top face (no side face touches it)
};

TopFace plate() {
  const TetMesh m = structured_box(Vec3(0.05, 0.04, 0.01), 5, 4, 1);
  TopFace t;
  t.faces = extract_boundary(m.tets);
  t.x = m.nodes;
  for (const Vec3& p : m.nodes)
    t.interior.push_back(p.z() > 0.01 - 1e-12 && p.x() > 1e-12 && p.x() < 0.05 - 1e-12 &&
                         p.y() > 1e-12 && p.y() < 0.04 - 1e-12);
  return t;
}

}  // namespace surface_pressure_test

using namespace surface_pressure_test;

TEST_CASE("Uniform pressure on a patch is recovered exactly on the patch's faces", "[fields]") {
  // F_i = -p0 n A_i on the nodes inside the top face (A_i: a third of the area of the triangles
  // around i, all on the top face): every triangle whose three nodes are inside reads p0.
  // Tolerance 1e-12 relative: sums of a few areas.
  const TopFace t = plate();
  const double p0 = 2500.0;
  std::vector<double> node_area(t.x.size(), 0.0);
  for (const Triangle& f : t.faces)
    for (int i : f) node_area[static_cast<size_t>(i)] += triangle_area(f, t.x) / 3.0;
  std::vector<Vec3> force(t.x.size(), Vec3::Zero());
  for (size_t i = 0; i < t.x.size(); ++i)
    if (t.interior[i]) force[i] = -p0 * Vec3::UnitZ() * node_area[i];
  const std::vector<double> p = face_contact_pressure(t.faces, t.x, force);
  int inside = 0, untouched = 0;
  for (size_t f = 0; f < t.faces.size(); ++f) {
    const Triangle& tri = t.faces[f];
    const bool all_in = t.interior[static_cast<size_t>(tri[0])] &&
                        t.interior[static_cast<size_t>(tri[1])] &&
                        t.interior[static_cast<size_t>(tri[2])];
    const bool none_in = !t.interior[static_cast<size_t>(tri[0])] &&
                         !t.interior[static_cast<size_t>(tri[1])] &&
                         !t.interior[static_cast<size_t>(tri[2])];
    if (all_in) {
      ++inside;
      CHECK(p[f] == Approx(p0).epsilon(1e-12));
    } else if (none_in) {
      ++untouched;
      CHECK(p[f] == 0.0);
    }
  }
  CHECK(inside == 2 * 3 * 2);  // the 3 x 2 inner cells of the 5 x 4 top, 2 triangles each
  CHECK(untouched > 0);
}

TEST_CASE("Face tractions carry exactly the nodal forces: sum_f t_f A_f = sum_i F_i", "[fields]") {
  // Force balance of the recovery, any forces. Tolerance 1e-12 of sum |F_i|: round-off.
  const TopFace t = plate();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> force(t.x.size());
  Vec3 total = Vec3::Zero();
  double scale = 0.0;
  for (Vec3& F : force) {
    F = Vec3(u(rng), u(rng), u(rng));
    total += F;
    scale += F.norm();
  }
  std::vector<Vec3> traction;
  face_contact_pressure(t.faces, t.x, force, &traction);
  Vec3 carried = Vec3::Zero();
  for (size_t f = 0; f < t.faces.size(); ++f)
    carried += traction[f] * triangle_area(t.faces[f], t.x);
  CHECK((carried - total).norm() <= 1e-12 * scale);
}
