// The per-tet fields against closed forms (docs/fields.md). Tolerances: 1e-12 relative, the
// round-off of a 3x3 inverse and a few products (the closed forms are exact).
#include <catch2/catch.hpp>
#include <cmath>

#include "io/fields/element_fields.hpp"
#include "tests/support/models.hpp"

using namespace ccm;
using namespace ccm::fields;

namespace element_fields_test {

constexpr double kTol = 1e-12;

Lame lame(double E, double nu) { return lame_from({MaterialModel::neo_hookean, E, nu, 1000.0}); }

}  // namespace element_fields_test

using namespace element_fields_test;

TEST_CASE("Neo-Hookean von Mises: uniaxial stretch and simple shear closed forms", "[fields]") {
  const Lame l = lame(1e6, 0.3);
  SECTION("uniaxial stretch F = diag(a, 1, 1): sigma_11 - sigma_22 = mu (a^2 - 1) / a") {
    for (double a : {0.8, 1.0, 1.25}) {
      Mat3 F = Mat3::Identity();
      F(0, 0) = a;
      const Mat3 sigma = cauchy_stress(MaterialModel::neo_hookean, l, F);
      // sigma = mu/J (b - I) + lambda ln(J)/J I with J = a, b = diag(a^2, 1, 1)
      CHECK(sigma(1, 1) == Approx(l.lambda * std::log(a) / a).margin(kTol * l.mu));
      CHECK(von_mises(sigma) == Approx(l.mu * std::abs(a * a - 1.0) / a).margin(kTol * l.mu));
    }
  }
  SECTION("simple shear F = I + g e1 e2: J = 1, von Mises = mu sqrt(g^4 + 3 g^2)") {
    for (double g : {0.01, 0.3, 1.0}) {
      Mat3 F = Mat3::Identity();
      F(0, 1) = g;
      const Mat3 sigma = cauchy_stress(MaterialModel::neo_hookean, l, F);
      CHECK(sigma(0, 1) == Approx(l.mu * g).epsilon(kTol));
      CHECK(von_mises(sigma) == Approx(l.mu * std::sqrt(g * g * g * g + 3 * g * g)).epsilon(kTol));
    }
  }
  SECTION("a rigid rotation carries no stress") {
    const Mat3 R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
    CHECK(von_mises(cauchy_stress(MaterialModel::neo_hookean, l, R)) <= kTol * l.mu);
  }
}

TEST_CASE("Linear elastic von Mises: uniaxial strain gives 2 mu |eps|", "[fields]") {
  const Lame l = lame(2e5, 0.25);
  for (double eps : {-0.01, 0.002}) {
    Mat3 F = Mat3::Identity();
    F(0, 0) = 1.0 + eps;
    const Mat3 sigma = cauchy_stress(MaterialModel::linear_elastic, l, F);
    CHECK(von_mises(sigma) == Approx(2.0 * l.mu * std::abs(eps)).epsilon(kTol));
  }
}

TEST_CASE("Per-tet J and von Mises of a homogeneously deformed mesh", "[fields]") {
  // Every tet of a box under x = F X has the same F: J = det F and the closed form above.
  Model model = test::box_model(Vec3(0.02, 0.01, 0.01), 3, 2, 2, test::neo_hookean(1e6, 0.3, 1000));
  Mat3 F = Mat3::Identity();
  F(0, 0) = 1.1;
  F(0, 1) = 0.2;
  F(2, 2) = 0.95;
  std::vector<Vec3> x;
  for (const Vec3& X : model.mesh.X) x.push_back(F * X);
  const std::vector<double> J = tet_volume_ratio(model.elements, x);
  const std::vector<double> vm = tet_von_mises(model.elements, x);
  REQUIRE(J.size() == model.mesh.tets.size());
  REQUIRE(vm.size() == model.mesh.tets.size());
  const double expected_vm =
      von_mises(cauchy_stress(MaterialModel::neo_hookean, model.elements.blocks[0].lame, F));
  for (size_t e = 0; e < J.size(); ++e) {
    CHECK(J[e] == Approx(F.determinant()).epsilon(kTol));
    CHECK(vm[e] == Approx(expected_vm).epsilon(1e-10));  // F from 4 nodes: a few ulps more
  }
}
