// The calibration's spread (rig_models/calibrate/parameter_profile.hpp) against closed forms: on
// f = f* + a (x - b)^2 + c (y - d)^2 the three-point curvature is 2a exactly at any spacing, the
// half-width of a 5 % rise is sqrt(0.05 f* / a), a best on a bound is flagged and profiled
// inside the range, a flat direction is unidentified and a failed evaluation leaves no figure.
#include <catch2/catch.hpp>
#include <cmath>

#include "rig_models/calibrate/parameter_profile.hpp"

using namespace ccm::rig;

TEST_CASE("profile: the three-point curvature of a parabola is exact at any spacing",
          "[rig][calibrate]") {
  const auto f = [](double x) { return 3.0 + 7.0 * (x - 0.4) * (x - 0.4); };
  CHECK(three_point_curvature(0.1, f(0.1), 0.35, f(0.35), 0.9, f(0.9)) == Approx(14.0));
  CHECK(three_point_curvature(-1.0, f(-1.0), 0.0, f(0.0), 1.0, f(1.0)) == Approx(14.0));
}

TEST_CASE("profile: half-widths, a best on its bound, a flat direction, a failed run",
          "[rig][calibrate]") {
  const double f_star = 0.2, a = 0.8, c = 50.0;
  int calls = 0;
  const SearchObjective objective = [&](const std::vector<double>& x) -> std::optional<double> {
    ++calls;
    return f_star + a * (x[0] - 0.5) * (x[0] - 0.5) + c * (x[1] - 0.0) * (x[1] - 0.0);
  };
  // x on [0, 1] with its best inside; y on [0, 2] with its best on the lower bound.
  const std::vector<SearchParameter> p = {{"x", 0.0, 1.0, 0.5}, {"y", 0.0, 2.0, 1.0}};
  const auto spread = profile_parameters(p, {0.5, 0.0}, f_star, objective);
  REQUIRE(spread.size() == 2);
  // Round-off only: the objective is a parabola in each direction.
  CHECK(*spread[0].curvature == Approx(2.0 * a).epsilon(1e-12));
  CHECK(*spread[0].half_width == Approx(std::sqrt(0.05 * f_star / a)).epsilon(1e-12));
  CHECK_FALSE(spread[0].on_lower_bound);
  CHECK_FALSE(spread[0].on_upper_bound);
  CHECK(spread[1].on_lower_bound);
  CHECK(*spread[1].curvature == Approx(2.0 * c).epsilon(1e-12));
  CHECK(calls == 2 + 3);  // the interior best reuses f*; the one on its bound needs a centre
  // A direction the objective does not see, and one whose run fails.
  const SearchObjective flat_in_x = [&](const std::vector<double>& x) -> std::optional<double> {
    if (x[1] > 0.3) return std::nullopt;  // the profile of y reaches 0.4
    return f_star + c * x[1] * x[1];
  };
  const auto other = profile_parameters(p, {0.5, 0.0}, f_star, flat_in_x);
  CHECK(other[0].curvature.has_value());
  CHECK_FALSE(other[0].half_width.has_value());  // unidentified
  CHECK_FALSE(other[1].curvature.has_value());   // its run at y = 0.4 failed
}

TEST_CASE("profile: every point in one batch, the same spread as one at a time",
          "[rig][calibrate]") {
  const SearchObjective f = [](const std::vector<double>& x) -> std::optional<double> {
    return 0.3 + 2.0 * (x[0] - 0.2) * (x[0] - 0.2) + 9.0 * (x[1] - 1.9) * (x[1] - 1.9) +
           0.5 * x[2] * x[2];
  };
  // The first best inside its range, the second near its upper bound, the third on its lower.
  const std::vector<SearchParameter> p = {
      {"a", 0.0, 1.0, 0.5}, {"b", 0.0, 2.0, 1.0}, {"c", 0.0, 4.0, 1.0}};
  const std::vector<double> best{0.2, 1.9, 0.0};
  std::vector<size_t> batches;
  const BatchObjective batch = [&](const std::vector<std::vector<double>>& points) {
    batches.push_back(points.size());
    return one_at_a_time(f)(points);
  };
  const auto together = profile_parameters(p, best, 0.3, batch);
  const auto apart = profile_parameters(p, best, 0.3, f);
  REQUIRE(batches == std::vector<size_t>{2 + 3 + 3});
  REQUIRE(together.size() == 3);
  for (size_t i = 0; i < 3; ++i) {
    CHECK(together[i].curvature == apart[i].curvature);
    CHECK(together[i].half_width == apart[i].half_width);
  }
  CHECK(*together[0].curvature == Approx(4.0).epsilon(1e-9));
  CHECK(*together[1].curvature == Approx(18.0).epsilon(1e-9));
  CHECK(*together[2].curvature == Approx(1.0).epsilon(1e-9));
}
