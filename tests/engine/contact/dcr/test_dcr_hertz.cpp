// Evidence (contact) 1, default-suite variant: Hertz impact of two identical elastic spheres at
// a coarse uniform mesh (2 mm, a_max / h = 0.85; tests/support/hertz.hpp; the refined runs are
// tests/validation/). Measured: duration -4.3 %, peak force -0.9 %. That closeness is partly a
// cancellation of coarse-mesh errors: the refined runs read about -8 % and +9 to +12 %
// (tests/validation/test_hertz_validation.cpp). The bounds, 10 % and 15 %, are that refined
// error level plus margin: this is a regression guard on the contact response (a contact that
// lost its persistence or its momentum exchange moves both figures by far more), not the
// evidence itself.
#include <catch2/catch.hpp>

#include "tests/support/hertz.hpp"
#include "tests/support/tolerance.hpp"

using namespace ccm;

TEST_CASE("DCR Hertz: two elastic spheres, coarse mesh", "[dcr][hertz]") {
  test::HertzCase c;
  c.mesh_size = 0.002;
  const test::HertzRun r = test::run_hertz(c);
  INFO("verdict " << to_string(r.summary.verdict) << " " << r.summary.instability.reason
                  << ", energy balance error " << r.summary.energy_balance_error);
  INFO("elements " << r.elements << ", steps " << r.summary.steps << ", a_max "
                   << r.hertz.contact_radius << " m (h = " << c.mesh_size << "), t_c / (2R/c) "
                   << r.hertz.duration / r.hertz.wave_time);
  INFO("duration " << r.duration << " s vs " << r.hertz.duration << " (rel "
                   << test::relative_error(r.duration, r.hertz.duration) << "), peak force "
                   << r.force_max << " N vs " << r.hertz.force_max << " (rel "
                   << test::relative_error(r.force_max, r.hertz.force_max) << ")");
  INFO("work: projection " << r.work_parts.projection << " J, impulses " << r.work_parts.impulses
                           << " J, restitution " << r.work_parts.restitution << " J, injected "
                           << r.injected << " J, initial KE " << r.initial_kinetic << " J; steps "
                           << r.summary.steps << ", contact-limited " << r.summary.limiters.contact
                           << ", dt_contact_min " << r.summary.dt_contact_min << ", dt_initial "
                           << r.summary.dt_initial << ", energy balance "
                           << r.summary.energy_balance_error);
  REQUIRE(r.summary.verdict == Verdict::completed);
  CHECK(r.momentum_error < 1e-10);
  CHECK(test::relative_error(r.duration, r.hertz.duration) < 0.10);
  CHECK(test::relative_error(r.force_max, r.hertz.force_max) < 0.15);
  // Energy (issue 15 item 4): measured 2.6e-5 at -O3 and -O2 (FMA contraction) and at -O1
  // (none); it read 0.8 % and 5.0 % while the step alternated between a full and a 0.33 step
  // at every output time. 0.1 % is the bound on the spread between builds. The
  // contact's net work is dissipation (the constraints hand 8x the impact energy back and
  // forth between projection and impulses; their net must not be positive beyond round-off).
  CHECK(r.summary.energy_balance_error < 1e-3);
  CHECK(r.injected < 1e-3 * r.initial_kinetic);
  // No step collapse (issue 15 item 3): no contact-limited step below 0.1 x the structural one.
  CHECK(
      (r.summary.limiters.contact == 0 || r.summary.dt_contact_min >= 0.1 * r.summary.dt_initial));
}
