// The CFC filters (correlate/cfc_filter.hpp): their measured gain against the analytic response
// of CFC.3 run forward and backward and against the SAE J211-1 corridor at its reference
// frequencies, zero phase, and what they leave unchanged.
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "correlate/cfc_filter.hpp"

using ccm::correlate::cfc_filter;
using ccm::correlate::design_cfc;

namespace {

constexpr double kPi = std::numbers::pi;

// The gain of one sinusoid through the filter, measured: a sine of `hz` filtered, then the
// amplitude of its middle half fitted by least squares to sin and cos at `hz` (the ends, where
// the padding acts, are left out).
double measured_gain_db(double cfc, double dt, double hz) {
  const int periods = 40;
  const int n = std::max(4000, static_cast<int>(periods / (hz * dt)));
  std::vector<double> x(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) x[static_cast<std::size_t>(k)] = std::sin(2 * kPi * hz * k * dt);
  const std::vector<double> y = cfc_filter(x, cfc, dt);
  double ss = 0, sc = 0, cc = 0, ys = 0, yc = 0;
  for (int k = n / 4; k < 3 * n / 4; ++k) {
    const double s = std::sin(2 * kPi * hz * k * dt), c = std::cos(2 * kPi * hz * k * dt);
    const double v = y[static_cast<std::size_t>(k)];
    ss += s * s, sc += s * c, cc += c * c, ys += v * s, yc += v * c;
  }
  const double det = ss * cc - sc * sc;
  const double a = (ys * cc - yc * sc) / det, b = (yc * ss - ys * sc) / det;
  return 20.0 * std::log10(std::hypot(a, b));
}

// |H(e^{jw})|^2 of CFC.3 (forward and backward square the two-pole gain), in dB.
double analytic_gain_db(double cfc, double dt, double hz) {
  const auto c = design_cfc(cfc, dt);
  const std::complex<double> z1 = std::polar(1.0, -2 * kPi * hz * dt);  // z^-1
  const std::complex<double> h =
      (c.a0 + c.a1 * z1 + c.a2 * z1 * z1) / (1.0 - c.b1 * z1 - c.b2 * z1 * z1);
  return 20.0 * std::log10(std::norm(h));
}

// The SAE J211-1 corridor (docs/correlation.md, as we read the standard's figure and table):
// F_H the class frequency and F_N its "N" frequency (1,650 Hz for CFC 1000, 1,000 for 600, 300
// for 180, 100 for 60); +0.5 / -0.5 dB from 0.1 Hz to F_H, +0.5 / -1 dB at F_H, +0.5 / -4 dB at
// F_N; above F_N the upper bound falls 9 dB per octave (down to a floor of -30 dB for CFC 60 and
// 180, -40 dB for 600 and 1000) and the lower bound 24 dB per octave.
struct Bounds {
  double lower, upper;
};
double n_frequency(double cfc) {
  return cfc == 1000 ? 1650.0 : cfc == 600 ? 1000.0 : cfc == 180 ? 300.0 : 100.0;
}
Bounds j211_corridor(double cfc, double hz) {
  const double fh = cfc, fn = n_frequency(cfc);
  if (hz <= fh) return {hz < fh ? -0.5 : -1.0, 0.5};
  if (hz <= fn) {  // the lower bound runs from -1 dB at F_H to -4 dB at F_N on a log axis
    const double s = std::log(hz / fh) / std::log(fn / fh);
    return {-1.0 - 3.0 * s, 0.5};
  }
  const double octaves = std::log2(hz / fn);
  const double floor_db = cfc <= 180 ? -30.0 : -40.0;
  return {-4.0 - 24.0 * octaves, std::max(0.5 - 9.0 * octaves, floor_db)};
}

}  // namespace

TEST_CASE("CFC filters: the measured gain is the analytic one and lies in the J211 corridor",
          "[correlate]") {
  const double dt = 1e-4;  // 10 kHz
  for (double cfc : ccm::correlate::kStandardCfcClasses) {
    const double fn = n_frequency(cfc);
    for (double hz : {cfc / 10, cfc / 2, cfc, 0.5 * (cfc + fn), fn, 1.5 * fn, 2 * fn}) {
      if (hz >= 0.45 / dt) continue;  // within the 10 kHz record's band
      INFO("CFC " << cfc << " at " << hz << " Hz");
      const double g = measured_gain_db(cfc, dt, hz);
      // The fit over 20 whole periods recovers the sinusoid's amplitude to ~1e-6; 1e-3 dB is a
      // hundredth of the corridor's finest step (0.5 dB) and far above that.
      CHECK(g == Approx(analytic_gain_db(cfc, dt, hz)).margin(1e-3));
      const Bounds b = j211_corridor(cfc, hz);
      CHECK(g >= b.lower);
      CHECK(g <= b.upper);
    }
  }
}

TEST_CASE("CFC filters: -3 dB near 1.67 times the class, -0.45 dB at the class", "[correlate]") {
  // The forward-backward pass of a two-pole Butterworth designed at 2.0775 CFC has the amplitude
  // gain |H|^2 = 1 / (1 + (f / 2.0775 CFC)^4) before the bilinear warping: -3 dB where
  // (f / 2.0775 CFC)^4 = sqrt(2) - 1, f = 0.802 x 2.0775 CFC = 1.667 CFC, and
  // 20 log10(1 / (1 + 0.4813^4)) = -0.454 dB at f = CFC.
  const double dt = 1e-5;  // 100 kHz: far from Nyquist, the warping is negligible
  CHECK(analytic_gain_db(1000, dt, 1666.0) == Approx(-3.0).margin(0.05));
  CHECK(analytic_gain_db(1000, dt, 1000.0) == Approx(-0.454).margin(0.005));
}

TEST_CASE("CFC filters: zero phase, and lines pass unchanged", "[correlate]") {
  const double dt = 1e-4;
  SECTION("a symmetric pulse keeps its peak time and its symmetry") {
    const int n = 2001, centre = 1000;
    std::vector<double> x(n);
    for (int k = 0; k < n; ++k) x[k] = std::exp(-std::pow((k - centre) * dt / 0.002, 2));
    for (double cfc : {60.0, 180.0, 600.0}) {
      const auto y = cfc_filter(x, cfc, dt);
      const auto peak = std::max_element(y.begin(), y.end()) - y.begin();
      CHECK(peak == centre);
      for (int k = 1; k < 500; ++k) CHECK(y[centre - k] == Approx(y[centre + k]).margin(1e-9));
      CHECK(y[centre] < x[centre]);  // and it was filtered
    }
  }
  SECTION("a constant and a straight line are unchanged, ends included") {
    std::vector<double> line(500);
    for (int k = 0; k < 500; ++k) line[k] = 3.0 - 0.01 * k;
    const auto y = cfc_filter(line, 60, dt);
    for (int k = 0; k < 500; ++k) CHECK(y[k] == Approx(line[k]).margin(1e-9));
  }
}

TEST_CASE("CFC filters: a class the sample rate cannot carry is refused", "[correlate]") {
  const std::vector<double> x(100, 1.0);
  CHECK_THROWS_WITH(cfc_filter(x, 1000, 1.0 / 4000),
                    Catch::Contains("CFC 1000 needs samples faster than"));
  CHECK_THROWS_AS(cfc_filter(x, 0, 1e-4), std::invalid_argument);
  CHECK_THROWS_AS(cfc_filter(x, 60, -1e-4), std::invalid_argument);
  CHECK_THROWS_AS(cfc_filter(std::vector<double>{1.0, 2.0}, 60, 1e-4), std::invalid_argument);
  std::vector<double> nan = x;
  nan[50] = std::nan("");
  CHECK_THROWS_AS(cfc_filter(nan, 60, 1e-4), std::invalid_argument);
}
