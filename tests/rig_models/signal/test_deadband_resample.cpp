// The sensor deadband and sampling at other timestamps, on synthetic signals.
#include <catch2/catch.hpp>
#include <stdexcept>

#include "rig_models/signal/deadband.hpp"
#include "rig_models/signal/resample.hpp"
#include "tests/support/tolerance.hpp"

using namespace ccm::rig;
using ccm::test::relative_error;

TEST_CASE("deadband: values below the threshold read 0, the rest unchanged", "[rig]") {
  const TimeSeries p{{0.0, 1.0, 2.0, 3.0, 4.0, 5.0}, {0.5, 0.999, 1.0, 3.0, -0.2, 0.0}};
  const TimeSeries out = apply_deadband(p, 1.0);
  CHECK(out.t == p.t);
  CHECK(out.value == std::vector<double>{0.0, 0.0, 1.0, 3.0, 0.0, 0.0});
  // a zero threshold zeroes only negative readings
  CHECK(apply_deadband(p, 0.0).value == std::vector<double>{0.5, 0.999, 1.0, 3.0, 0.0, 0.0});
  CHECK_THROWS_WITH(apply_deadband(p, -1.0),
                    "deadband: threshold must be finite and >= 0 (got -1)");
}

TEST_CASE("resample: linear interpolation at the requested times, never extrapolated", "[rig]") {
  // v(t) = 3 t - 1 on an uneven grid is reproduced exactly (to rounding) anywhere inside
  const TimeSeries line{{0.0, 0.1, 0.35, 1.0}, {-1.0, -0.7, 0.05, 2.0}};
  const std::vector<double> times = {0.0, 0.05, 0.1, 0.2, 0.9, 1.0};
  const TimeSeries s = sample_at(line, times);
  CHECK(s.t == times);
  for (size_t i = 0; i < times.size(); ++i)
    CHECK(std::abs(s.value[i] - (3.0 * times[i] - 1.0)) < 1e-15);
  // a kink is not smoothed: between two samples, the straight line through them
  const TimeSeries kink{{0.0, 1.0, 2.0}, {0.0, 4.0, 0.0}};
  CHECK(sample_at(kink, std::vector<double>{0.25, 1.5}).value == std::vector<double>{1.0, 2.0});
  CHECK_THROWS_WITH(sample_at(kink, std::vector<double>{2.5}),
                    "resample: time 2.5 s is outside the signal's [0, 2] s");
  CHECK(times_inside(kink, std::vector<double>{-1.0, 0.0, 1.0, 2.0, 2.5}) ==
        std::vector<double>{0.0, 1.0, 2.0});
}
