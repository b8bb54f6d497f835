// The kernels' ln J (kernel_log, engine/element/lanes.hpp): within one ulp of std::log on the
// series' whole range and at its edges, the vector log outside it (a pack with one lane out of
// range takes the vector log for every lane), NaN kept.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>

#include "engine/element/lanes.hpp"

using namespace ccm;

namespace {

// |a - b| in units of the last place of b.
double ulps(double a, double b) {
  const double ulp = std::nextafter(std::abs(b), INFINITY) - std::abs(b);
  return std::abs(a - b) / ulp;
}

Lanes filled(double v) { return Lanes{} + v; }

}  // namespace

TEST_CASE("kernel_log: within one ulp of std::log where the series runs", "[element][lanes]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> offset(-kSeriesLogRange, kSeriesLogRange);
  std::uniform_real_distribution<double> decade(-16.0, std::log10(kSeriesLogRange));
  double worst = 0.0;
  for (int pack = 0; pack < 20000; ++pack) {
    Lanes J;
    for (int l = 0; l < kLanes; ++l) {
      // Half the lanes uniform over the range, half spread over the decades of |J - 1| (the
      // series' small terms), each rounded to a double near 1 as a kernel's J would be.
      const double x =
          (l % 2 == 0) ? offset(rng) : ((rng() & 1) ? 1.0 : -1.0) * std::pow(10.0, decade(rng));
      J[l] = 1.0 + x;
    }
    REQUIRE(all_lanes_near_one(J));
    const Lanes got = kernel_log(J);
    for (int l = 0; l < kLanes; ++l) {
      if (J[l] == 1.0) {
        REQUIRE(got[l] == 0.0);
        continue;
      }
      worst = std::max(worst, ulps(got[l], std::log(J[l])));
    }
  }
  INFO("largest error " << worst << " ulp");
  CHECK(worst <= 1.0);
}

TEST_CASE("kernel_log: the series' range edges and the vector log outside it", "[element][lanes]") {
  const double inside = std::nextafter(1.0 + kSeriesLogRange, 0.0);
  const double below = std::nextafter(1.0 - kSeriesLogRange, 2.0);
  CHECK(all_lanes_near_one(filled(inside)));
  CHECK(all_lanes_near_one(filled(below)));
  CHECK_FALSE(all_lanes_near_one(filled(1.0 + kSeriesLogRange)));
  CHECK_FALSE(all_lanes_near_one(filled(1.0 - kSeriesLogRange)));
  CHECK(ulps(kernel_log(filled(inside))[0], std::log(inside)) <= 1.0);
  CHECK(ulps(kernel_log(filled(below))[0], std::log(below)) <= 1.0);

  // One lane far from 1: the whole pack goes to the vector log, bit for bit.
  Lanes J = filled(1.001);
  J[kLanes - 1] = 0.3;
  CHECK_FALSE(all_lanes_near_one(J));
  const Lanes got = kernel_log(J), want = vector_log(J);
  for (int l = 0; l < kLanes; ++l) CHECK(got[l] == want[l]);
  CHECK(ulps(got[kLanes - 1], std::log(0.3)) <= 4.0);  // libmvec's bound

  // NaN (an inverted tet's reported lane is set to 1 by the kernels; a NaN position is not):
  // out of the series' range, and NaN out.
  J = filled(1.0);
  J[0] = std::numeric_limits<double>::quiet_NaN();
  CHECK_FALSE(all_lanes_near_one(J));
  CHECK(std::isnan(kernel_log(J)[0]));
  CHECK(kernel_log(J)[1] == 0.0);
}
