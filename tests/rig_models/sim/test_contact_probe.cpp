// The sensor's contact force as the thesis measured it (3.3.3, eq. 3.8's F_c): the probe around
// the DCR sums m (v_after - v_before) of the sensor's nodes over the contact steps. Two bars
// end-on: all the momentum the struck bar gets comes through the contact, so the probe's impulse
// over its contact face equals that bar's final momentum, and the wrapped model's figures are
// passed through unchanged: each of ContactModel's nine hooks, and the contact-energy check of
// a run through the probe.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "engine/contact/dcr/dcr_contact.hpp"
#include "rig_models/sim/contact_probe.hpp"
#include "tests/support/models.hpp"
#include "tests/support/tolerance.hpp"
#include "tests/support/two_bodies.hpp"

using namespace ccm;

TEST_CASE("contact probe: the impulse on the struck face is the struck bar's momentum",
          "[rig][probe]") {
  const double L = 0.05, w = 0.01, E = 1e6, rho = 1000.0, v0 = 0.1, gap = 1e-4;
  const MaterialParams mat{MaterialModel::neo_hookean, E, 0.0, rho};
  ModelMesh mesh;
  add_body(mesh, "a", mat, structured_box(Vec3(L, w, w), 5, 2, 2));
  add_body(mesh, "b", mat,
           test::translated(structured_box(Vec3(L, w, w), 5, 2, 2), Vec3(L + gap, 0.0, 0.0)));
  Model model = make_model(std::move(mesh));
  const Body& a = model.mesh.bodies[0];
  for (int n = a.first_node; n < a.first_node + a.n_nodes; ++n)
    model.initial_velocity[static_cast<size_t>(n)] = Vec3(v0, 0.0, 0.0);
  dcr::DcrSettings settings;
  settings.surfaces = {"a/boundary", "b/boundary"};
  settings.restitution = 1.0;
  dcr::DcrContact dcr(model.mesh, settings, model.bcs.fixed_nodes);
  // The sensor: b's whole surface. (Its face toward a alone misses the small impulses of the
  // contacts at its rim, which also move the side triangles' inner nodes: 4e-8 of the total.)
  rig::ContactProbe probe(dcr, model.mesh.node_sets.at("b/boundary"), Vec3::UnitX());
  CHECK(probe.name() == "dcr");
  RunOptions opt;
  opt.contact = &probe;
  opt.time.end_time = gap / v0 + 2 * L / std::sqrt(E / rho) + 5e-3;
  double v_b = 0.0;
  opt.on_sample = [&](const State& s) { v_b = test::mean_velocity(s, model.mesh.bodies[1]).x(); };
  const RunSummary r = run_explicit(model, opt);
  REQUIRE(r.verdict == Verdict::completed);
  const double mass_b = rho * L * w * w;  // the lumped masses sum to rho V exactly
  const double p_b = v_b;
  INFO("probe impulse " << probe.impulse() << " N s, b's momentum " << mass_b * p_b);
  CHECK(v_b > 0.9 * v0);  // the velocities were exchanged (e = 1)
  // Only contact acts on b, and only on its surface nodes: round-off.
  CHECK(test::relative_error(probe.impulse(), mass_b * p_b) < 1e-10);
  CHECK(probe.ledger().work == dcr.work());
}

namespace {

// A contact model whose every hook leaves a trace: the calls it received, and figures no
// default returns (so that a probe that does not forward one reads the default instead). Its
// correction speeds every node up by the factor (1 + gain) and books the kinetic energy it adds
// as its work, all of it injected (the engine's contact-energy check test does the same), plus
// `extra_injection` (so that the figure differs from work()).
class Recorder : public ContactModel {
 public:
  Recorder(double gain, double extra_injection)
      : ContactModel("recorder"), gain_(gain), extra_(extra_injection) {}
  void begin_step(const State&, double) override { ++begin; }
  void add_forces(State&) override { ++forces; }
  void correct(State& s, double dt) override {
    ++corrections;
    for (size_t i = 0; i < s.v.size(); ++i) {
      const Vec3 before = s.v[i] + 0.5 * dt * s.a[i];
      s.v[i] *= 1.0 + gain_;
      const Vec3 after = s.v[i] + 0.5 * dt * s.a[i];
      work_ += 0.5 * s.m_lumped[i] * (after.squaredNorm() - before.squaredNorm());
    }
  }
  void end_step(const State&, double) override {
    ++end;
    ledger_ = {.work = work_,
               .injected_energy = std::max(0.0, work_) + extra_,
               .failure = failing ? "recorded failure" : ""};
  }
  ContactStepBound step_bound(const State&) const override {
    return {.stiffness_dt = 0.25, .kinematic_dt = 0.5};
  }

  int begin = 0, forces = 0, corrections = 0, end = 0;
  bool failing = false;

 private:
  double gain_, extra_;
  double work_ = 0.0;
};

}  // namespace

TEST_CASE("contact probe: every hook of the contact model is forwarded", "[rig][probe]") {
  Model model = test::box_model(Vec3(0.02, 0.02, 0.02), 1, 1, 1, test::neo_hookean(1e6, 0.3, 1e3));
  State s;
  s.x = model.mesh.X;
  s.v.assign(s.x.size(), Vec3(1.0, 0.0, 0.0));
  s.a.assign(s.x.size(), Vec3::Zero());
  s.m_lumped.assign(s.x.size(), 1.0);
  Recorder inner(0.5, 0.125);
  rig::ContactProbe probe(inner, {0}, Vec3::UnitX());
  const ContactModel& as_model = probe;  // through the interface, as the integrator calls it
  probe.begin_step(s, 1e-3);
  probe.add_forces(s);
  probe.correct(s, 1e-3);
  probe.end_step(s, 1e-3);
  CHECK(inner.begin == 1);
  CHECK(inner.forces == 1);
  CHECK(inner.corrections == 1);
  CHECK(inner.end == 1);
  CHECK(as_model.name() == "recorder");
  CHECK(as_model.step_bound(s).stiffness_dt == 0.25);
  CHECK(as_model.step_bound(s).kinematic_dt == 0.5);
  CHECK(inner.ledger().work > 0.0);
  CHECK(as_model.ledger().work == inner.ledger().work);
  // A probe that did not take the inner ledger would read 0, not the model's figure.
  CHECK(as_model.ledger().injected_energy == inner.ledger().work + 0.125);
  CHECK(as_model.ledger().failure.empty());
  inner.failing = true;
  probe.end_step(s, 1e-3);
  CHECK(as_model.ledger().failure == "recorded failure");
  // The probe read the correction: node 0 (mass 1) went from 1 to 1.5 m/s along x.
  CHECK(probe.impulse() == 0.5);
}

TEST_CASE("contact probe: a run through the probe keeps the contact-energy check", "[rig][probe]") {
  // A free box at 1 m/s whose contact model injects 0.2 % of the kinetic energy per step: the
  // monitor ends the run at its first check (see the engine's contact-energy check test). Through
  // the probe the run must end the same way; a probe that drops injected_energy runs on.
  Model model = test::box_model(Vec3(0.02, 0.02, 0.02), 2, 2, 2, test::neo_hookean(1e6, 0.3, 1e3));
  for (Vec3& v : model.initial_velocity) v = Vec3(1.0, 0.0, 0.0);
  Recorder injecting(1e-3, 0.0);
  rig::ContactProbe probe(injecting, {0}, Vec3::UnitX());
  RunOptions opt;
  opt.contact = &probe;
  opt.time.end_time = 20e-3;
  const RunSummary r = run_explicit(model, opt);
  INFO(r.instability.reason);
  CHECK(r.verdict == Verdict::unstable);
  CHECK(r.instability.reason.find("contact (recorder) put") != std::string::npos);
}
