// The rig's run parameters by name (rig_models/sim/run_parameters.hpp): every name --set and
// calibration accept is read back as set, an unknown one is refused, and a Fixed case's pin
// gains both friction coefficients when one is set.
#include <catch2/catch.hpp>

#include "rig_models/sim/run_parameters.hpp"

using namespace ccm::rig;

TEST_CASE("run parameters: each name reads back what was set", "[rig]") {
  RunParameters p;
  double value = 0.125;
  for (const std::string_view name : kRunParameterNames) {
    INFO(name);
    set_parameter(p, name, value);
    CHECK(get_parameter(p, name) == value);
    value += 0.5;
  }
  // Each name is its own slot: the first still reads its value after the others were set.
  CHECK(get_parameter(p, kRunParameterNames.front()) == 0.125);
  CHECK_THROWS_WITH(get_parameter(p, "mu_x"), Catch::Contains("unknown rig parameter 'mu_x'"));
  CHECK_THROWS_WITH(set_parameter(p, "mu_x", 1.0), Catch::Contains("unknown rig parameter 'mu_x'"));
  RunParameters fixed;  // a Fixed case: no pin friction until one coefficient is set
  set_parameter(fixed, "mu_k", 0.3);
  REQUIRE(fixed.mu_s);
  CHECK(*fixed.mu_s == kFrictionalFixedMuS);
  CHECK(*fixed.mu_k == 0.3);
}
