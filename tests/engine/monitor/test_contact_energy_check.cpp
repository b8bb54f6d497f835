// The monitor ends a run whose contact model injects energy (ContactModel::injected_energy):
// a model that books its work exactly keeps the energy balance, so only this check sees it.
// Set-up: a free box moving at 1 m/s, with a fake constraint-type contact model that speeds
// every node up by a factor (1 + k) per step and books the kinetic energy it adds as its work.
#include <catch2/catch.hpp>
#include <limits>
#include <string>

#include "engine/contact/contact_model.hpp"
#include "tests/support/models.hpp"

using namespace ccm;

namespace {

class Accelerator : public ContactModel {
 public:
  Accelerator(double gain, bool injection_counts)
      : ContactModel("accelerator", kCorrectionPhases), gain_(gain), counts_(injection_counts) {}
  void begin_step(const State& /*s*/, double /*dt*/) override {}
  void add_forces(State& /*s*/) override {}
  void end_step(const State& /*s*/, double /*dt*/) override {
    ledger_ = {};
    ledger_.work = work_;
    ledger_.injected_energy = counts_ ? std::max(0.0, work_) : 0.0;
  }
  ContactStepBound step_bound(const State& /*s*/, double /*ceiling*/) const override { return {}; }
  double corrected_elements_stable_dt() const override {
    return std::numeric_limits<double>::infinity();
  }
  void correct(State& s, double dt) override {
    for (size_t i = 0; i < s.v.size(); ++i) {
      const Vec3 v_end_before = s.v[i] + 0.5 * dt * s.a[i];
      s.v[i] *= 1.0 + gain_;
      const Vec3 v_end = s.v[i] + 0.5 * dt * s.a[i];
      work_ += 0.5 * s.m_lumped[i] * (v_end.squaredNorm() - v_end_before.squaredNorm());
    }
  }

 private:
  double gain_;
  bool counts_;
  double work_ = 0.0;
};

RunSummary run_with(Accelerator& contact) {
  Model model = test::box_model(Vec3(0.02, 0.02, 0.02), 2, 2, 2, test::neo_hookean(1e6, 0.3, 1e3));
  for (Vec3& v : model.initial_velocity) v = Vec3(1.0, 0.0, 0.0);
  RunOptions opt;
  opt.contact = &contact;
  opt.time.end_time = 20e-3;  // ~280 steps of ~70 us; the monitor checks every 50
  return run_explicit(model, opt);
}

}  // namespace

TEST_CASE("the monitor stops a contact model that injects energy, and says so",
          "[monitor][contact]") {
  // 1e-3 per step: the kinetic energy grows 0.2 % per step, so at the first check (step 50) the
  // injected energy is 10 % of the kinetic energy, twice the 5 % tolerance.
  Accelerator injecting(1e-3, true);
  const RunSummary r = run_with(injecting);
  INFO(r.instability.reason);
  CHECK(r.verdict == Verdict::unstable);
  CHECK(r.instability.reason.find("contact (accelerator) put") != std::string::npos);
  CHECK(r.instability.reason.find("can only dissipate") != std::string::npos);
  // The booked work keeps the balance itself: the energy-balance check did not fire.
  CHECK(r.energy_balance_error < 0.01);

  // The same model reporting no injection (a model exchanging energy with the outside) runs on.
  Accelerator external(1e-3, false);
  CHECK(run_with(external).verdict == Verdict::completed);
}
