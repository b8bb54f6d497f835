// Evidence 1: the Neo-Hookean stress is the derivative of its energy, vanishes at rest and
// reduces to linear elasticity for small strain.
#include <catch2/catch.hpp>
#include <random>

#include "engine/material/linear_elastic.hpp"
#include "engine/material/neo_hookean.hpp"
#include "tests/support/tolerance.hpp"

using namespace ccm;

namespace {

Mat3 cofactor(const Mat3& F) { return F.determinant() * F.inverse().transpose(); }

Mat3 neo_hookean_P(const Mat3& F, const Lame& l) {
  return neo_hookean::first_piola(F, cofactor(F), F.determinant(), l);
}

// dW/dF_ij by central differences with step h.
Mat3 finite_difference_P(const Mat3& F, const Lame& l, double h) {
  Mat3 P;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Mat3 Fp = F, Fm = F;
      Fp(i, j) += h;
      Fm(i, j) -= h;
      P(i, j) =
          (neo_hookean::strain_energy_density(Fp, l) - neo_hookean::strain_energy_density(Fm, l)) /
          (2.0 * h);
    }
  return P;
}

const Lame kLame = lame_from({MaterialModel::neo_hookean, 1.0e6, 0.3, 1000.0});

}  // namespace

TEST_CASE("Neo-Hookean P equals the finite difference of W at random F with J > 0", "[material]") {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> perturb(-0.3, 0.3);
  int tested = 0;
  while (tested < 50) {
    Mat3 F = Mat3::Identity();
    for (int k = 0; k < 9; ++k) F(k / 3, k % 3) += perturb(rng);
    if (F.determinant() < 0.2) continue;
    // Central differences have truncation error O(h^2 W''') ~ 1e-10 relative at h = 1e-5 and
    // round-off ~ eps W / h ~ 1e-11: 1e-6 relative (the figure) has ample margin.
    const Mat3 P = neo_hookean_P(F, kLame);
    const Mat3 P_fd = finite_difference_P(F, kLame, 1e-5 * std::max(1.0, F.norm()));
    CHECK(test::relative_error(P, P_fd) < 1e-6);
    ++tested;
  }
}

TEST_CASE("Neo-Hookean stress and energy vanish at F = I", "[material]") {
  const Mat3 I = Mat3::Identity();
  CHECK(neo_hookean_P(I, kLame).norm() == 0.0);
  CHECK(neo_hookean::strain_energy_density(I, kLame) == 0.0);
}

TEST_CASE("Neo-Hookean agrees with linear elasticity at strain 1e-6", "[material]") {
  Mat3 H;
  H << 0.3, -0.7, 0.2, 0.5, 1.0, -0.4, 0.1, 0.6, -0.8;
  const Mat3 F = Mat3::Identity() + 1e-6 * H;
  const Mat3 P = neo_hookean_P(F, kLame);
  const Mat3 sigma = linear_elastic::stress(F, kLame);
  // The difference is second order in strain (~1e-6 relative) plus the skew part the
  // linear model drops (also ~1e-6 relative for this H): 1e-5 is the stated bound.
  CHECK(test::relative_error(P, sigma) < 1e-5);
}

TEST_CASE("Material validation names the bad field", "[material]") {
  CHECK(validate({MaterialModel::neo_hookean, 1.0, 0.3, 1.0}).empty());
  CHECK(validate({MaterialModel::neo_hookean, -1.0, 0.3, 1.0}).rfind("E ", 0) == 0);
  CHECK(validate({MaterialModel::neo_hookean, 1.0, 0.5, 1.0}).rfind("nu ", 0) == 0);
  CHECK(validate({MaterialModel::neo_hookean, 1.0, 0.3, 0.0}).rfind("rho ", 0) == 0);
}
