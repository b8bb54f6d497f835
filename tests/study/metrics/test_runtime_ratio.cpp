// Normalised runtime, total runtime and runtime ratio (eqs. 2.40-2.43) against hand values.
#include <catch2/catch.hpp>
#include <stdexcept>

#include "study/metrics/runtime_ratio.hpp"
#include "tests/support/tolerance.hpp"

using namespace ccm::study;
using ccm::test::relative_error;

TEST_CASE("NT = AIR / ISTS, TR = t_f NT, RTR = NT_ccm / NT_rigid", "[metrics]") {
  const double nt_ccm = normalised_runtime(4e-3, 1e-6);    // 4000 s/s
  const double nt_rigid = normalised_runtime(1e-3, 2e-6);  // 500 s/s
  CHECK(relative_error(nt_ccm, 4000.0) < 1e-15);
  CHECK(relative_error(nt_rigid, 500.0) < 1e-15);
  CHECK(relative_error(total_runtime(0.15, nt_ccm), 600.0) < 1e-15);  // thesis t_f = 0.15 s
  CHECK(relative_error(runtime_ratio(nt_ccm, nt_rigid), 8.0) < 1e-15);
}

TEST_CASE("runtime figures refuse non-positive inputs", "[metrics]") {
  CHECK_THROWS_AS(normalised_runtime(0.0, 1e-6), std::invalid_argument);
  CHECK_THROWS_AS(normalised_runtime(1e-3, 0.0), std::invalid_argument);
  CHECK_THROWS_AS(runtime_ratio(1.0, 0.0), std::invalid_argument);
}
