// The projection update (engine/contact/dcr/projection_update.hpp) against the element kernel:
// moving some surface nodes of a deformed body changes the stored energy and the nodal forces by
// exactly what two full kernel evaluations, before and after the move, give. Both materials, and
// the nodal-pressure tet, whose volumetric forces change one ring of elements further out.
// Tolerance 1e-9 relative: the two paths compute the same element quantities in a different
// order (the kernel in AVX lanes with the vector log), so they agree to round-off of the sums.
#include <catch2/catch.hpp>
#include <random>
#include <vector>

#include "engine/contact/dcr/projection_update.hpp"
#include "engine/element/internal_force.hpp"
#include "engine/element/tet4.hpp"
#include "engine/mesh/structured_box.hpp"
#include "tests/support/models.hpp"
#include "tests/support/tolerance.hpp"

using namespace ccm;

namespace {

struct Evaluation {
  std::vector<Vec3> f;
  double energy;
};

Evaluation kernel(const Model& model, const std::vector<Vec3>& x) {
  Evaluation e{std::vector<Vec3>(x.size(), Vec3::Zero()), 0.0};
  std::vector<double> block_energy(model.elements.blocks.size(), 0.0);
  add_internal_forces(model.elements, x, e.f, block_energy);
  for (double b : block_energy) e.energy += b;
  return e;
}

Model box(MaterialModel material, double nu, ElementKind element) {
  ModelMesh mesh;
  add_body(mesh, "box", {material, 1e6, nu, 1000.0},
           structured_box(Vec3(0.03, 0.02, 0.01), 6, 4, 2));
  mesh.bodies.back().element = element;
  return make_model(std::move(mesh));
}

void check_against_kernel(MaterialModel material, double nu = 0.3,
                          ElementKind element = ElementKind::tet4) {
  Model model = box(material, nu, element);
  const ModelMesh& mesh = model.mesh;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-2e-4, 2e-4);
  State s;
  s.x = mesh.X;
  for (Vec3& p : s.x)
    p += Vec3(jitter(rng), jitter(rng), jitter(rng)) + 0.05 * p.z() * Vec3::UnitX();
  s.v.assign(s.x.size(), Vec3(0.1, -0.2, 0.3));
  s.a.assign(s.x.size(), Vec3::Zero());
  std::vector<double> inv_m(s.x.size(), 0.0);
  for (size_t i = 0; i < inv_m.size(); ++i) inv_m[i] = 1.0 + 0.01 * static_cast<double>(i);

  const std::vector<int>& surface = mesh.node_sets.at("box/boundary");
  std::vector<int> moved;
  std::vector<Vec3> before;
  for (size_t k = 0; k < surface.size(); k += 3) {
    moved.push_back(surface[k]);
    before.push_back(s.x[static_cast<size_t>(surface[k])]);
  }
  const Evaluation old_eval = kernel(model, s.x);
  for (int n : moved) s.x[static_cast<size_t>(n)] += Vec3(jitter(rng), jitter(rng), jitter(rng));
  const Evaluation new_eval = kernel(model, s.x);

  const double dt = 1e-5;
  dcr::ProjectionUpdate update(mesh, surface);
  const double dE = update.apply(moved, before, s, inv_m, dt).total();

  double expected_dE = new_eval.energy - old_eval.energy;
  double force_scale = 0.0;
  for (size_t i = 0; i < s.x.size(); ++i) {
    const Vec3 df = new_eval.f[i] - old_eval.f[i];
    expected_dE += 0.5 * dt * s.v[i].dot(df);
    force_scale = std::max(force_scale, old_eval.f[i].norm());
  }
  INFO("dE " << dE << " vs kernel " << expected_dE);
  CHECK(test::relative_error(dE, expected_dE) < 1e-9);
  for (size_t i = 0; i < s.x.size(); ++i) {
    const Vec3 expected = inv_m[i] * (new_eval.f[i] - old_eval.f[i]);
    INFO("node " << i);
    REQUIRE((s.a[i] - expected).norm() <= 1e-9 * inv_m[i] * force_scale);
  }
}

}  // namespace

TEST_CASE("projection update: energy and force changes equal the kernel's (Neo-Hookean)",
          "[dcr][projection_update]") {
  check_against_kernel(MaterialModel::neo_hookean);
}

TEST_CASE("projection update: energy and force changes equal the kernel's (linear elastic)",
          "[dcr][projection_update]") {
  check_against_kernel(MaterialModel::linear_elastic);
}

TEST_CASE("projection update: energy and force changes equal the kernel's (nodal pressure)",
          "[dcr][projection_update][nodal_pressure]") {
  check_against_kernel(MaterialModel::neo_hookean, 0.3, ElementKind::nodal_pressure);
  check_against_kernel(MaterialModel::neo_hookean, 0.499, ElementKind::nodal_pressure);
}

namespace {

// The mesh at rest in its reference positions.
State at_rest(const ModelMesh& mesh) {
  State s;
  s.x = mesh.X;
  s.v.assign(s.x.size(), Vec3::Zero());
  s.a.assign(s.x.size(), Vec3::Zero());
  return s;
}

// A projection that squeezes the box's top layer: every third top node pushed down by 60 % of a
// cell. The stable step the update reports for the elements around the moved nodes is the
// kernel's over the whole squeezed mesh (its shortest elements are the squeezed ones), to
// round-off (1e-9 relative, as above: the kernel's lanes and vector log against scalar code), and
// shorter than the step measured before the squeeze, which the next step would otherwise take.
void check_squeezed_stable_dt(MaterialModel material) {
  Model model = box(material, 0.45, ElementKind::tet4);
  const ModelMesh& mesh = model.mesh;
  State s = at_rest(mesh);
  const std::vector<double> inv_m(s.x.size(), 1.0);
  const std::vector<int>& surface = mesh.node_sets.at("box/boundary");
  std::vector<int> moved;
  std::vector<Vec3> before;
  for (size_t k = 0; k < surface.size(); k += 3) {
    const auto n = static_cast<size_t>(surface[k]);
    if (s.x[n].z() < 0.01 - 1e-12) continue;  // the top face only
    moved.push_back(surface[k]);
    before.push_back(s.x[n]);
  }
  REQUIRE(moved.size() >= 4);
  std::vector<Vec3> f(s.x.size(), Vec3::Zero());
  const double dt_before = add_internal_forces(model.elements, s.x, f).stable_dt;
  const double cell = 0.01 / 2.0;
  for (int n : moved) s.x[static_cast<size_t>(n)].z() -= 0.6 * cell;
  const double dt_after = add_internal_forces(model.elements, s.x, f).stable_dt;

  dcr::ProjectionUpdate update(mesh, surface);
  const double dt_update = update.apply(moved, before, s, inv_m, 1e-6).stable_dt;
  INFO("stable dt: before " << dt_before << ", kernel after " << dt_after << ", update "
                            << dt_update);
  CHECK(dt_after < 0.8 * dt_before);
  CHECK(test::relative_error(dt_update, dt_after) < 1e-9);
}

}  // namespace

TEST_CASE("projection update: the stable step of the squeezed elements is the kernel's",
          "[dcr][projection_update]") {
  check_squeezed_stable_dt(MaterialModel::neo_hookean);
  check_squeezed_stable_dt(MaterialModel::linear_elastic);
}

// Eq. PJ.1 (docs/time-step.md): the update reports the largest move of a node over the height of
// a tet around it, at the moved positions. Here nodes of the box's top face moved down by 60 % of
// a cell, some by 30 %: the ratio is the largest of move / characteristic_length over the tets
// that hold a moved node, computed here from the mesh itself (to round-off), and 0 for no move.
TEST_CASE("projection update: the largest move over the height of the tets around it",
          "[dcr][projection_update]") {
  Model model = box(MaterialModel::neo_hookean, 0.45, ElementKind::tet4);
  const ModelMesh& mesh = model.mesh;
  State s = at_rest(mesh);
  const std::vector<double> inv_m(s.x.size(), 1.0);
  const std::vector<int>& surface = mesh.node_sets.at("box/boundary");
  dcr::ProjectionUpdate update(mesh, surface);
  CHECK(update.apply({}, {}, s, inv_m, 1e-6).jump_ratio == 0.0);

  const double cell = 0.01 / 2.0;
  std::vector<int> moved;
  std::vector<Vec3> before;
  std::vector<double> move(s.x.size(), 0.0);
  for (size_t k = 0; k < surface.size(); k += 3) {
    const auto n = static_cast<size_t>(surface[k]);
    if (s.x[n].z() < 0.01 - 1e-12) continue;  // the top face only
    moved.push_back(surface[k]);
    before.push_back(s.x[n]);
    move[n] = (moved.size() % 2 == 0 ? 0.6 : 0.3) * cell;
    s.x[n].z() -= move[n];
  }
  REQUIRE(moved.size() >= 4);
  double expected = 0.0;
  for (const Tet& t : mesh.tets) {
    double largest = 0.0;
    for (int n : t) largest = std::max(largest, move[static_cast<size_t>(n)]);
    if (largest == 0.0) continue;
    const Mat3 Ds = edge_matrix(s.x[static_cast<size_t>(t[0])], s.x[static_cast<size_t>(t[1])],
                                s.x[static_cast<size_t>(t[2])], s.x[static_cast<size_t>(t[3])]);
    expected = std::max(expected, largest / characteristic_length(Ds));
  }
  const double ratio = update.apply(moved, before, s, inv_m, 1e-6).jump_ratio;
  INFO("jump ratio " << ratio << ", from the mesh " << expected);
  CHECK(expected > 0.3);  // a move of 0.6 cell against tets a cell or less high
  CHECK(test::relative_error(ratio, expected) < 1e-12);
}
