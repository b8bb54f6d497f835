// Evidence (contact) 1, [validation]: Hertz impact of two identical elastic spheres
// (tests/support/hertz.hpp) at the validation mesh and refined: contact duration within 5 % and
// peak contact force within 10 % of the closed form (contact-method.md 6a), and both errors
// shrinking with the mesh size. The meshes are refined at the contact poles
// (tests/support/refined_sphere.hpp): 0.8 and 0.5 mm there, 2.5 mm elsewhere.
//
// Status (docs/contact-persistent.md): this test FAILS on the duration. Measured on this
// branch: duration -9.0 % / -7.5 %, peak force +11.7 % / +9.4 % (0.8 / 0.5 mm); uniform meshes
// 1.4 / 1.0 mm: -8.5 % / -8.3 %, +12.3 % / +9.0 %. The FE model is stiffer than Hertz and the
// error shrinks only slowly with the contact mesh; it does not come from the two-pass node-face
// contacts or the edge-edge contacts (each switched off in turn: no change), nor mainly from
// dynamics (v = 0.1 m/s: -7.8 %, +13 %).
#include <catch2/catch.hpp>

#include "tests/support/hertz.hpp"
#include "tests/support/tolerance.hpp"

using namespace ccm;

namespace {

struct HertzErrors {
  double duration, force;
};

HertzErrors errors_at(double contact_size) {
  test::HertzCase c;
  c.mesh_size = 0.0025;
  c.contact_size = contact_size;
  const double mesh_size = contact_size;
  const test::HertzRun r = test::run_hertz(c);
  const HertzErrors e{test::relative_error(r.duration, r.hertz.duration),
                      test::relative_error(r.force_max, r.hertz.force_max)};
  WARN("h = " << mesh_size << " m: " << r.elements << " elements, " << r.summary.steps
              << " steps, a_max / h = " << r.hertz.contact_radius / mesh_size
              << ", t_c / (2R/c) = " << r.hertz.duration / r.hertz.wave_time << "; duration "
              << r.duration << " s vs " << r.hertz.duration << " (" << e.duration
              << "), peak force " << r.force_max << " N vs " << r.hertz.force_max << " (" << e.force
              << "), verdict " << to_string(r.summary.verdict));
  REQUIRE(r.summary.verdict == Verdict::completed);
  CHECK(r.momentum_error < 1e-10);
  return e;
}

}  // namespace

TEST_CASE("Hertz impact of two spheres converges to the closed form", "[validation][hertz]") {
  const HertzErrors coarse = errors_at(0.0008);
  const HertzErrors fine = errors_at(0.0005);
  CHECK(fine.duration < 0.05);
  CHECK(fine.force < 0.10);
  CHECK(fine.duration + fine.force < coarse.duration + coarse.force);
}
