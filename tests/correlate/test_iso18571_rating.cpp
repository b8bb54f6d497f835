// The ISO/TS 18571 rating (correlate/iso18571_rating.hpp) against the published values of an
// independent implementation and against cases computed by hand.
#include <catch2/catch.hpp>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "correlate/iso18571_rating.hpp"

using ccm::correlate::CurveRating;
using ccm::correlate::iso18571_rating;
using ccm::correlate::RatingGrade;

namespace {

constexpr double kDt = 1e-4;  // 10 kHz, the rate the standard prescribes

// f(t_k) at t_k = t0 + k dt for t_k < t_end (the samples numpy.arange gives).
template <class F>
std::vector<double> sampled(double t0, int count, F f) {
  std::vector<double> v;
  for (int k = 0; k < count; ++k) v.push_back(f(t0 + k * kDt));
  return v;
}

}  // namespace

// TU Graz's public Python implementation (github.com/VSI-TUGraz/objective-rating-metric, README,
// docs/correlation.md) publishes the two overall ratings below to three decimals; ours must round
// to the same three decimals, so the tolerance is half a unit of the last published digit.
TEST_CASE("ISO 18571: a 30 % larger sine rates 0.713 as published", "[correlate]") {
  const auto ref = sampled(0.0, 1500, [](double t) { return std::sin(20.0 * t); });
  const auto cmp = sampled(0.0, 1500, [](double t) { return 1.3 * std::sin(20.0 * t); });
  const CurveRating r = iso18571_rating(ref, cmp, kDt);
  CHECK(r.overall == Approx(0.713).margin(5e-4));
  CHECK(r.shift_samples == 0);
  CHECK(r.phase == 1.0);
  CHECK(r.grade == RatingGrade::fair);
}

TEST_CASE("ISO 18571: a sine lagging by 10 ms rates 0.815 as published", "[correlate]") {
  // Reference sin(20 (t - 0.02)), comparison sin(20 (t - 0.03)), both sampled at 10 kHz on their
  // common window t in [0.03, 0.17): 1,400 samples.
  const auto ref = sampled(0.03, 1400, [](double t) { return std::sin(20.0 * (t - 0.02)); });
  const auto cmp = sampled(0.03, 1400, [](double t) { return std::sin(20.0 * (t - 0.03)); });
  const CurveRating r = iso18571_rating(ref, cmp, kDt);
  CHECK(r.overall == Approx(0.815).margin(5e-4));
  CHECK(r.shift_samples == 100);  // the comparison lags by 100 samples
  CHECK(r.grade == RatingGrade::good);
}

TEST_CASE("ISO 18571: identical curves rate 1 on every score", "[correlate]") {
  const auto ref =
      sampled(0.0, 800, [](double t) { return std::exp(-std::pow((t - 0.04) / 0.01, 2)); });
  const CurveRating r = iso18571_rating(ref, ref, kDt);
  CHECK(r.corridor == 1.0);
  CHECK(r.phase == 1.0);
  CHECK(r.magnitude == 1.0);
  CHECK(r.slope == 1.0);
  CHECK(r.overall == Approx(1.0).epsilon(1e-15));
  CHECK(r.grade == RatingGrade::excellent);
}

TEST_CASE("ISO 18571: each score against a case computed by hand", "[correlate]") {
  SECTION("a constant 20 % high: corridor, magnitude and the overall rating") {
    // T = 1, C = 1.2: |C - T| = 0.2 lies between the corridors 0.05 and 0.5, so every sample
    // scores ((0.5 - 0.2) / 0.45)^2 = 4/9; constants have no shift (E_P = 1) and no slope
    // (E_S = 1); the warping path is the diagonal, e_M = 0.2 and E_M = (0.5 - 0.2) / 0.5 = 0.6;
    // R = 0.4 (4/9) + 0.2 + 0.12 + 0.2.
    const std::vector<double> ref(200, 1.0), cmp(200, 1.2);
    const CurveRating r = iso18571_rating(ref, cmp, kDt);
    CHECK(r.corridor == Approx(4.0 / 9.0).epsilon(1e-12));
    CHECK(r.phase == 1.0);
    CHECK(r.magnitude_error == Approx(0.2).epsilon(1e-12));
    CHECK(r.magnitude == Approx(0.6).epsilon(1e-12));
    CHECK(r.slope == 1.0);
    CHECK(r.overall == Approx(0.4 * 4.0 / 9.0 + 0.52).epsilon(1e-12));
  }
  SECTION("the corridor: half the samples inside the inner corridor, half outside the outer") {
    std::vector<double> ref(100, 2.0), cmp(100, 2.05);  // 0.05 < 0.05 * 2: inside
    for (int i = 50; i < 100; ++i) cmp[static_cast<std::size_t>(i)] = 3.2;  // 1.2 > 0.5 * 2
    CHECK(iso18571_rating(ref, cmp, kDt).corridor == Approx(0.5).epsilon(1e-12));
  }
  SECTION("the phase: a pulse delayed by 37 of 1,000 samples") {
    // The overlapping parts correlate exactly at the delay: n = 37, E_P = (200 - 37) / 200.
    auto pulse = [](double t) { return std::exp(-std::pow((t - 0.04) / 0.008, 2)); };
    const auto ref = sampled(0.0, 1000, pulse);
    const auto late = sampled(-37 * kDt, 1000, pulse);
    const auto early = sampled(37 * kDt, 1000, pulse);
    CHECK(iso18571_rating(ref, late, kDt).shift_samples == 37);
    CHECK(iso18571_rating(ref, late, kDt).phase == Approx(163.0 / 200.0).epsilon(1e-12));
    CHECK(iso18571_rating(ref, early, kDt).shift_samples == -37);
    CHECK(iso18571_rating(ref, early, kDt).phase == Approx(163.0 / 200.0).epsilon(1e-12));
  }
  SECTION("the slope: twice the reference has a slope error of exactly 1") {
    // Same shape, so no shift; every smoothed derivative doubles: e_S = 1, E_S = (2 - 1) / 2.
    const auto ref = sampled(0.0, 600, [](double t) { return std::sin(20.0 * t); });
    const auto cmp = sampled(0.0, 600, [](double t) { return 2.0 * std::sin(20.0 * t); });
    const CurveRating r = iso18571_rating(ref, cmp, kDt);
    CHECK(r.shift_samples == 0);
    CHECK(r.slope_error == Approx(1.0).epsilon(1e-12));
    CHECK(r.slope == Approx(0.5).epsilon(1e-12));
  }
  SECTION("an offset changes the corridor but not the slope") {
    const auto ref = sampled(0.0, 600, [](double t) { return std::sin(20.0 * t); });
    const auto cmp = sampled(0.0, 600, [](double t) { return std::sin(20.0 * t) + 0.3; });
    const CurveRating r = iso18571_rating(ref, cmp, kDt);
    CHECK(r.slope == Approx(1.0).epsilon(1e-12));
    // |C - T| = 0.3 everywhere, between the corridors 0.05 m and 0.5 m, m = max |T| = sin(1.198).
    const double m = std::sin(20.0 * 599 * kDt);
    CHECK(r.corridor == Approx(std::pow((0.5 * m - 0.3) / (0.45 * m), 2)).epsilon(1e-9));
  }
}

TEST_CASE("ISO 18571: the grades' bounds", "[correlate]") {
  using ccm::correlate::rating_grade;
  CHECK(rating_grade(0.95) == RatingGrade::excellent);
  CHECK(rating_grade(0.94) == RatingGrade::good);
  CHECK(rating_grade(0.81) == RatingGrade::good);
  CHECK(rating_grade(0.80) == RatingGrade::fair);
  CHECK(rating_grade(0.59) == RatingGrade::fair);
  CHECK(rating_grade(0.58) == RatingGrade::poor);
  CHECK(ccm::correlate::grade_name(RatingGrade::good) == "good");
}

TEST_CASE("ISO 18571: curves it cannot rate are refused", "[correlate]") {
  const std::vector<double> ten(10, 1.0), eleven(11, 1.0), zeros(10, 0.0);
  std::vector<double> nan = ten;
  nan[3] = std::nan("");
  CHECK_THROWS_AS(iso18571_rating(ten, eleven, kDt), std::invalid_argument);
  CHECK_THROWS_AS(iso18571_rating(ten, nan, kDt), std::invalid_argument);
  CHECK_THROWS_AS(iso18571_rating(zeros, ten, kDt), std::invalid_argument);
  CHECK_THROWS_AS(iso18571_rating(ten, ten, 0.0), std::invalid_argument);
  CHECK_THROWS_AS(iso18571_rating(std::vector<double>(9, 1.0), std::vector<double>(9, 1.0), kDt),
                  std::invalid_argument);
}
