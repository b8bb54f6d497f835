// Cumulative (eqs. 2.34-2.36, as time averages: docs/metrics.md) and final-state (2.37-2.39)
// errors against hand-computed values and closed-form integrals.
#include <catch2/catch.hpp>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "study/metrics/model_errors.hpp"
#include "tests/support/tolerance.hpp"

using ccm::study::cumulative_error;
using ccm::study::final_state_error;
using ccm::test::relative_error;

// A handful of additions and one division: anything above a few ulps is a wrong formula.
constexpr double kRounding = 1e-14;

namespace {

// An analytic pair over [0, T]: c(t) = 1 + 3 t/T, r(t) = c(t) - a (t/T)^2 (a difference that
// grows, as a deformation does; not periodic, so the trapezoidal rule is not exact on it).
// Closed form: <(c - r)^2> = a^2 / 5, <c> = 5/2, <r> = 5/2 - a/3, so
//   e = (a^2 / 5) / (5/2 - a/6).
constexpr double kT = 0.15, kA = 0.5;
const double kClosedForm = (kA * kA / 5.0) / (2.5 - kA / 6.0);

struct Sampled {
  std::vector<double> t, c, r;
};

Sampled sample(const std::vector<double>& times) {
  Sampled s;
  for (double t : times) {
    const double tau = t / kT;
    s.t.push_back(t);
    s.c.push_back(1.0 + 3.0 * tau);
    s.r.push_back(1.0 + 3.0 * tau - kA * tau * tau);
  }
  return s;
}

std::vector<double> uniform_times(int intervals) {
  std::vector<double> t;
  for (int i = 0; i <= intervals; ++i) t.push_back(kT * i / intervals);
  return t;
}

double printed_sum(const Sampled& s) {  // the thesis's sum over samples, for contrast
  double sum = 0.0;
  for (std::size_t i = 0; i < s.c.size(); ++i) sum += (s.c[i] - s.r[i]) * (s.c[i] - s.r[i]);
  return sum;
}

}  // namespace

TEST_CASE("cumulative error is the time average of the squared difference over the mean level",
          "[metrics]") {
  // Trapezoids on t = 0, 1, 2, 3: c = 1, 2, 3, 4; r = 1, 1, 2, 2; (c - r)^2 = 0, 1, 1, 4.
  //   <(c - r)^2> = (0.5 + 1 + 2.5) / 3 = 4/3; <c> = (1.5 + 2.5 + 3.5) / 3 = 2.5;
  //   <r> = (1 + 1.5 + 2) / 3 = 1.5; e = (4/3) / 2 = 2/3.
  const std::vector<double> t = {0.0, 1.0, 2.0, 3.0};
  const std::vector<double> c = {1.0, 2.0, 3.0, 4.0};
  const std::vector<double> r = {1.0, 1.0, 2.0, 2.0};
  CHECK(relative_error(cumulative_error(t, c, r), 2.0 / 3.0) < kRounding);
  CHECK(relative_error(cumulative_error(t, r, c), 2.0 / 3.0) < kRounding);  // symmetric
  // Uniform samples need no times: the time average does not depend on the interval's size.
  CHECK(relative_error(cumulative_error(c, r), 2.0 / 3.0) < kRounding);
  const std::vector<double> t_ms = {0.0, 1e-3, 2e-3, 3e-3};
  CHECK(relative_error(cumulative_error(t_ms, c, r), 2.0 / 3.0) < kRounding);
}

TEST_CASE("cumulative error does not depend on how often the histories are sampled", "[metrics]") {
  const Sampled coarse = sample(uniform_times(30));  // dt = T / 30 (the study's 5 ms at 0.15 s)
  const Sampled fine = sample(uniform_times(60));    // dt / 2
  // Non-uniform: t_i = T (i/N)^1.5, dense at the start, the largest interval 1.5 T / N.
  std::vector<double> stretched;
  for (int i = 0; i <= 40; ++i) stretched.push_back(kT * std::pow(i / 40.0, 1.5));
  const Sampled uneven = sample(stretched);
  const double e_coarse = cumulative_error(coarse.t, coarse.c, coarse.r);
  const double e_fine = cumulative_error(fine.t, fine.c, fine.r);
  const double e_uneven = cumulative_error(uneven.t, uneven.c, uneven.r);
  INFO("closed form " << kClosedForm << ", dt " << e_coarse << ", dt/2 " << e_fine
                      << ", non-uniform " << e_uneven);
  // The criterion: halving the interval moves it by less than 1 %.
  CHECK(relative_error(e_fine, e_coarse) < 0.01);
  CHECK(relative_error(e_uneven, e_coarse) < 0.01);
  // Against the closed-form integral: the composite trapezoidal rule's error on (t/T)^4 is
  // h^2/3 (h = the interval in units of T) against its integral 1/5, i.e. 5 h^2 / 3 relative:
  // 1.9e-3 at h = 1/30, 4.6e-4 at 1/60, <= 2.4e-3 for the non-uniform largest h = 0.0375. The
  // denominator's terms are linear and quadratic (smaller errors). Bound: 3e-3.
  CHECK(relative_error(e_coarse, kClosedForm) < 3e-3);
  CHECK(relative_error(e_fine, kClosedForm) < 1e-3);
  CHECK(relative_error(e_uneven, kClosedForm) < 3e-3);
  // The printed sum over samples doubles when the interval halves (what this replaces).
  CHECK(printed_sum(fine) / printed_sum(coarse) > 1.9);
}

TEST_CASE("cumulative error scales with the data (no root is taken, as printed)", "[metrics]") {
  // <(k dc)^2> / (k mean) = k x the unscaled value: the printed formula is not scale-free
  // (the thesis's text says "root sum of squares"; 2.34 takes no root).
  const std::vector<double> c = {1.0, 2.0, 3.0, 4.0}, r = {1.0, 1.0, 2.0, 2.0};
  std::vector<double> c10, r10;
  for (double v : c) c10.push_back(10.0 * v);
  for (double v : r) r10.push_back(10.0 * v);
  CHECK(relative_error(cumulative_error(c10, r10), 20.0 / 3.0) < kRounding);
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

TEST_CASE("errors of identical or all-zero histories are zero, bad input is refused", "[metrics]") {
  const std::vector<double> zero(5, 0.0), a = {1.0, 3.0, 2.0};
  CHECK(cumulative_error(zero, zero) == 0.0);
  CHECK(final_state_error(zero, zero) == 0.0);
  CHECK(cumulative_error(a, a) == 0.0);
  CHECK(final_state_error(a, a) == 0.0);
  const std::vector<double> two = {1.0, 2.0}, one = {1.0}, empty;
  CHECK_THROWS_AS(cumulative_error(a, two), std::invalid_argument);
  CHECK_THROWS_AS(final_state_error(empty, empty), std::invalid_argument);
  CHECK_THROWS_AS(cumulative_error(one, one), std::invalid_argument);  // no interval
  const std::vector<double> t_back = {0.0, 2.0, 1.0}, t_short = {0.0, 1.0};
  CHECK_THROWS_AS(cumulative_error(t_back, a, a), std::invalid_argument);
  CHECK_THROWS_AS(cumulative_error(t_short, a, a), std::invalid_argument);
  // Means that cancel with a non-zero difference: the normalisation is undefined.
  const std::vector<double> p = {1.0, -1.0}, m = {-1.0, 1.0};
  CHECK_THROWS_AS(cumulative_error(p, m), std::domain_error);
}
