// The Richardson extrapolation of tests/support/richardson.hpp against quantities whose order and
// limit are known exactly: f(h) = f0 + C h^p on meshes of unequal ratios.
#include <catch2/catch.hpp>
#include <cmath>

#include "tests/support/richardson.hpp"

using namespace ccm;

TEST_CASE("Richardson: the order and limit of f0 + C h^p on three unequal meshes", "[richardson]") {
  for (const double p : {0.7, 1.0, 1.66, 2.0, 3.0}) {
    for (const double C : {-2.5, 4.0}) {
      const auto f = [&](double h) { return -1.3 + C * std::pow(h, p); };
      const auto r = test::richardson(0.32, f(0.32), 0.23, f(0.23), 0.08, f(0.08));
      REQUIRE(r.has_value());
      // Bisection to 1e-12 in p; the limit then carries that error times ln(h) C h^p: 1e-10.
      CHECK(r->order == Approx(p).margin(1e-9));
      CHECK(r->limit == Approx(-1.3).margin(1e-9));
    }
  }
}

TEST_CASE("Richardson: no order where the values do not converge monotonically", "[richardson]") {
  // Oscillating: the differences change sign.
  CHECK_FALSE(test::richardson(0.4, 1.0, 0.2, 1.2, 0.1, 1.1).has_value());
  // Monotone but diverging with refinement (the differences grow): no positive order.
  CHECK_FALSE(test::richardson(0.4, 1.0, 0.2, 1.1, 0.1, 1.4).has_value());
  // Meshes out of order, equal values on the two finest.
  CHECK_FALSE(test::richardson(0.1, 1.0, 0.2, 1.1, 0.4, 1.2).has_value());
  CHECK_FALSE(test::richardson(0.4, 1.0, 0.2, 1.1, 0.1, 1.1).has_value());
}
