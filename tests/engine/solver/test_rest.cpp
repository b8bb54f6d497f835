// A body at rest with no load stays `completed`: the energy monitor must not read round-off
// as an instability (its error is measured against a floor of 1e-12 M c_d^2).
#include <catch2/catch.hpp>

#include "tests/support/models.hpp"

using namespace ccm;

TEST_CASE("A body at rest with no load completes with zero energy error", "[stability]") {
  const Model model =
      test::box_model(Vec3(0.1, 0.05, 0.02), 4, 2, 1, test::neo_hookean(1e5, 0.45, 1000.0));
  RunOptions opt;
  opt.time.end_time = 2000 * reference_stable_dt(model.elements, model.mesh.X);
  opt.time.output_interval = opt.time.end_time / 10;
  opt.monitor.check_interval = 1;
  const RunSummary r = run_explicit(model, opt);
  CHECK(r.verdict == Verdict::completed);
  // At rest the strain energy is round-off, ~ eps (lambda + 2 mu) V = 1e-4 of the floor
  // 1e-12 M c_d^2 = 1e-12 (lambda + 2 mu) V; measured 1.1e-5. Far below the 5 % threshold.
  CHECK(r.energy_balance_error < 1e-3);
}
