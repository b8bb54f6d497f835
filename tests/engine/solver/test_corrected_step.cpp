// The step after a contact correction (docs/time-step.md, "After a contact correction"): the
// integrator takes dt_safety times the smaller of the structure's stable step, measured by the
// kernel before the correction, and the one the contact model reports for the elements it moved
// (ContactModel::corrected_elements_stable_dt). Set-up: a free box at 1 m/s and a stub contact
// model that moves nothing but reports a tenth of the box's stable step from its first correction
// on: every step after the first must be dt_safety times that report (the box alone would step
// ten times longer).
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "engine/contact/contact_model.hpp"
#include "engine/element/internal_force.hpp"
#include "tests/support/models.hpp"

using namespace ccm;

namespace {

class ShortStepReport : public ContactModel {
 public:
  explicit ShortStepReport(double stable_dt)
      : ContactModel("short step", kCorrectionPhases), stable_dt_(stable_dt) {}
  void begin_step(const State& /*s*/, double /*dt*/) override {}
  void add_forces(State& /*s*/) override {}
  void correct(State& /*s*/, double /*dt*/) override { corrected_ = true; }
  void end_step(const State& /*s*/, double /*dt*/) override {}
  ContactStepBound step_bound(const State& /*s*/, double /*ceiling*/) const override { return {}; }
  double corrected_elements_stable_dt() const override {
    return corrected_ ? stable_dt_ : std::numeric_limits<double>::infinity();
  }

 private:
  double stable_dt_;
  bool corrected_ = false;
};

}  // namespace

TEST_CASE("the step after a contact correction respects the corrected elements' stable step",
          "[integrator][contact]") {
  Model model = test::box_model(Vec3(0.02, 0.02, 0.02), 2, 2, 2, test::neo_hookean(1e6, 0.3, 1e3));
  for (Vec3& v : model.initial_velocity) v = Vec3(1.0, 0.0, 0.0);
  const double structure_dt = reference_stable_dt(model.elements, model.mesh.X);
  ShortStepReport contact(0.1 * structure_dt);
  RunOptions opt;
  opt.contact = &contact;
  opt.time.end_time = 100.0 * structure_dt;
  opt.time.output_interval = opt.time.end_time;
  const RunSummary r = run_explicit(model, opt);
  REQUIRE(r.verdict == Verdict::completed);
  const double short_dt = opt.time.dt_safety * 0.1 * structure_dt;
  INFO("structure's step " << structure_dt << " s, steps " << r.steps << ", dt_min " << r.dt_min
                           << ", dt_max " << r.dt_max);
  // The first step is the structure's (no correction yet); the others are the short one, less a
  // last step shortened to land on the end time. A box moving rigidly keeps its stable step, so
  // without the report the run would take about 111 steps.
  const double expected_steps = 1.0 + (opt.time.end_time - r.dt_first) / short_dt;
  CHECK(std::abs(static_cast<double>(r.steps) - expected_steps) <= 1.0);
  CHECK(r.dt_min <= short_dt * (1.0 + 1e-12));
}
