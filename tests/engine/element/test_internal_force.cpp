// The vectorized element kernel: its nodal forces are minus the gradient of the stored energy
// it reports, for both material models, on a deformed multi-pack mesh (padding lanes included).
#include <catch2/catch.hpp>
#include <cmath>

#include "engine/element/internal_force.hpp"
#include "engine/mesh/structured_box.hpp"
#include "tests/support/tolerance.hpp"

using namespace ccm;

namespace {

double total_energy(const ElementSet& es, const std::vector<Vec3>& x) {
  std::vector<Vec3> f(x.size(), Vec3::Zero());
  std::vector<double> energy(es.blocks.size(), 0.0);
  add_internal_forces(es, x, f, energy);
  double sum = 0.0;
  for (double e : energy) sum += e;
  return sum;
}

void check_forces_are_energy_gradient(MaterialModel model) {
  ModelMesh mesh;
  // 2 x 1 x 1 cells = 12 tets: three packs of four lanes, or two of eight with padding.
  add_body(mesh, "a", {model, 1e6, 0.3, 1000.0}, structured_box(Vec3(0.2, 0.1, 0.1), 2, 1, 1));
  add_body(mesh, "b", {model, 3e5, 0.45, 900.0}, structured_box(Vec3(0.1, 0.1, 0.1), 1, 1, 1));
  const ElementSet es = make_element_set(mesh);
  std::vector<Vec3> x(mesh.X.size());
  for (size_t i = 0; i < x.size(); ++i) {  // a smooth finite deformation, J well above 0
    const Vec3& X = mesh.X[i];
    x[i] = X + Vec3(0.05 * std::sin(10 * X.y()), 0.04 * X.x() * X.z() * 10, -0.03 * X.x());
  }
  std::vector<Vec3> f(x.size(), Vec3::Zero());
  add_internal_forces(es, x, f);
  const double h = 1e-7;
  double max_err = 0.0, max_f = 0.0;
  for (size_t n = 0; n < x.size(); ++n)
    for (int k = 0; k < 3; ++k) {
      std::vector<Vec3> xp = x, xm = x;
      xp[n][k] += h;
      xm[n][k] -= h;
      const double grad = (total_energy(es, xp) - total_energy(es, xm)) / (2 * h);
      max_err = std::max(max_err, std::abs(f[n][k] + grad));
      max_f = std::max(max_f, std::abs(f[n][k]));
    }
  // Central difference with h = 1e-7 m on coordinates ~0.1 m: truncation ~1e-12, round-off
  // ~ eps * E_total / h ~ 1e-9 relative to the forces; 1e-6 relative is a safe bound.
  INFO("max |f + dE/dx| = " << max_err << ", max |f| = " << max_f);
  CHECK(max_f > 0.0);
  CHECK(max_err / max_f < 1e-6);
}

}  // namespace

TEST_CASE("Kernel forces are minus the energy gradient (Neo-Hookean)", "[kernel]") {
  check_forces_are_energy_gradient(MaterialModel::neo_hookean);
}

TEST_CASE("Kernel forces are minus the energy gradient (linear elastic)", "[kernel]") {
  check_forces_are_energy_gradient(MaterialModel::linear_elastic);
}

TEST_CASE("Kernel reports an inverted element instead of producing non-finite forces", "[kernel]") {
  ModelMesh mesh;
  add_body(mesh, "a", {MaterialModel::neo_hookean, 1e6, 0.3, 1000.0},
           structured_box(Vec3(0.1, 0.1, 0.1), 1, 1, 1));
  const ElementSet es = make_element_set(mesh);
  std::vector<Vec3> x = mesh.X;
  x[7] = Vec3(-0.05, -0.05, -0.05);  // drag the far corner through the opposite corner
  std::vector<Vec3> f(x.size(), Vec3::Zero());
  const InternalForceResult r = add_internal_forces(es, x, f);
  CHECK(r.first_bad_element >= 0);
  CHECK(r.bad_J <= 0.0);
  for (const Vec3& fi : f) CHECK(fi.allFinite());
}

TEST_CASE("The stable step follows the current shape and the stiffening under compression",
          "[kernel]") {
  ModelMesh mesh;
  const MaterialParams mat{MaterialModel::neo_hookean, 1e6, 0.49, 1000.0};
  add_body(mesh, "a", mat, structured_box(Vec3(0.1, 0.1, 0.1), 1, 1, 1));
  const ElementSet es = make_element_set(mesh);
  const double dt_ref = reference_stable_dt(es, mesh.X);
  const Lame l = lame_from(mat);
  for (double s : {1.0, 0.9, 0.8, 1.2}) {  // uniform scaling x = s X
    std::vector<Vec3> x(mesh.X.size());
    for (size_t i = 0; i < x.size(); ++i) x[i] = s * mesh.X[i];
    std::vector<Vec3> f(x.size(), Vec3::Zero());
    const double dt = add_internal_forces(es, x, f).stable_dt;
    // h scales with s; the modulus is M = lambda (1 + 2 |ln J|) + mu (2 + max(tr C - 3, 0)).
    const double J = s * s * s, trC = 3 * s * s;
    const double M =
        l.lambda * (1 + 2 * std::abs(std::log(J))) + l.mu * (2 + std::max(trC - 3, 0.0));
    const double expected = s * dt_ref * std::sqrt((l.lambda + 2 * l.mu) / M);
    INFO("s = " << s << ": dt = " << dt << ", expected " << expected);
    CHECK(test::relative_error(dt, expected) < 1e-12);
  }
}
