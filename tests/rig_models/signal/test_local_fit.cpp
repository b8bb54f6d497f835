// The local quadratic fit (Savitzky-Golay on arbitrary times) behind the open-loop drive's
// dV_i/dt: exact on quadratics, ends included; noise on a line averaged down.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "rig_models/signal/local_fit.hpp"

using namespace ccm::rig;

TEST_CASE("local fit: a quadratic and its slope are reproduced exactly, ends included",
          "[rig][signal]") {
  TimeSeries s;
  for (int k = 0; k < 40; ++k) {
    const double t = 0.01 * k + (k % 3 == 0 ? 0.002 : 0.0);  // uneven steps
    s.t.push_back(t);
    s.value.push_back(0.3 - 2.0 * t + 5.0 * t * t);
  }
  const LocalFit f = local_quadratic_fit(s, 0.02);
  for (size_t k = 0; k < s.t.size(); ++k) {
    CHECK(f.value.value[k] == Approx(s.value[k]).margin(1e-12));
    CHECK(f.derivative.value[k] == Approx(-2.0 + 10.0 * s.t[k]).margin(1e-9));
  }
}

TEST_CASE("local fit: noise on a ramp is averaged, too few samples refused", "[rig][signal]") {
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.002);  // 2 mm/s, motion-capture-like
  TimeSeries s;
  for (int k = 0; k < 100; ++k) {
    s.t.push_back(0.01 * k);
    s.value.push_back(2.9 * 0.01 * k + noise(rng));
  }
  const LocalFit f = local_quadratic_fit(s, 0.02);
  double worst = 0.0;
  for (size_t k = 5; k + 5 < s.t.size(); ++k)
    worst = std::max(worst, std::abs(f.derivative.value[k] - 2.9));
  // A plain difference of neighbours would scatter by sqrt(2) 0.002 / 0.01 = 0.28 m/s^2; the
  // five-point fit's slope scatters by 0.002 / sqrt(sum s^2) = 0.063 m/s^2 (1 sigma): 0.25 is 4
  // sigma over the 90 interior samples.
  CHECK(worst < 0.25);
  CHECK_THROWS_WITH(local_quadratic_fit({{0.0, 1.0, 2.0}, {1.0, 2.0, 3.0}}, 0.5),
                    "local fit input: 3 samples, at least 4 needed");
}
