// Cumulative (eqs. 2.34-2.36) and final-state (2.37-2.39) errors against hand-computed values.
#include <catch2/catch.hpp>
#include <stdexcept>
#include <vector>

#include "study/metrics/model_errors.hpp"
#include "tests/support/tolerance.hpp"

using ccm::study::cumulative_error;
using ccm::study::final_state_error;
using ccm::test::relative_error;

// A handful of additions and one division: anything above a few ulps is a wrong formula.
constexpr double kRounding = 1e-14;

TEST_CASE("cumulative error is the printed sum of squares over the mean of means", "[metrics]") {
  // diffs 0, 1, 1, 2 -> sum 6; means 2.5 and 1.5 -> (2.5 + 1.5) / 2 = 2; 6 / 2 = 3
  const std::vector<double> c = {1.0, 2.0, 3.0, 4.0};
  const std::vector<double> r = {1.0, 1.0, 2.0, 2.0};
  CHECK(relative_error(cumulative_error(c, r), 3.0) < kRounding);
  // Symmetric in the two models.
  CHECK(relative_error(cumulative_error(r, c), 3.0) < kRounding);
}

TEST_CASE("cumulative error as printed scales with the data (no root is taken)", "[metrics]") {
  // sum (k dc)^2 / (k mean) = k x the unscaled value: the printed formula is not
  // scale-free (the thesis's text says "root sum of squares"; 2.34 takes no root).
  const std::vector<double> c = {1.0, 2.0, 3.0, 4.0}, r = {1.0, 1.0, 2.0, 2.0};
  std::vector<double> c10, r10;
  for (double v : c) c10.push_back(10.0 * v);
  for (double v : r) r10.push_back(10.0 * v);
  CHECK(relative_error(cumulative_error(c10, r10), 30.0) < kRounding);
}

TEST_CASE("final-state error is |c(t_f) - r(t_f)| over the largest magnitude", "[metrics]") {
  // |1 - 4| / max(max|c| = 5, max|r| = 4) = 0.6 (the -5 shows the absolute value is taken)
  const std::vector<double> c = {0.0, 2.0, -5.0, 1.0};
  const std::vector<double> r = {0.0, 1.0, 3.0, 4.0};
  CHECK(relative_error(final_state_error(c, r), 0.6) < kRounding);
  // Scale-free: the same for the data x 1e-6.
  std::vector<double> cs, rs;
  for (double v : c) cs.push_back(1e-6 * v);
  for (double v : r) rs.push_back(1e-6 * v);
  CHECK(relative_error(final_state_error(cs, rs), 0.6) < kRounding);
}

TEST_CASE("errors of identical or all-zero histories are zero; bad input is refused", "[metrics]") {
  const std::vector<double> zero(5, 0.0), a = {1.0, 3.0, 2.0};
  CHECK(cumulative_error(zero, zero) == 0.0);
  CHECK(final_state_error(zero, zero) == 0.0);
  CHECK(cumulative_error(a, a) == 0.0);
  CHECK(final_state_error(a, a) == 0.0);
  const std::vector<double> two = {1.0, 2.0}, empty;
  CHECK_THROWS_AS(cumulative_error(a, two), std::invalid_argument);
  CHECK_THROWS_AS(final_state_error(empty, empty), std::invalid_argument);
  // Means that cancel with a non-zero difference: the normalisation is undefined.
  const std::vector<double> p = {1.0, -1.0}, m = {-1.0, 1.0};
  CHECK_THROWS_AS(cumulative_error(p, m), std::domain_error);
}
