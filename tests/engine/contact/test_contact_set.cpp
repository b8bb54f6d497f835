// The contact models of one run act as one (engine/contact/contact_set.hpp): forces sum,
// corrections act in order, the step bounds combine as springs on one mass matrix, the ledger
// sums and names the member that failed.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "engine/contact/contact_set.hpp"

using namespace ccm;

namespace {

// A stub with a fixed force on node 0, a correction that doubles v*[0], a given bound and ledger.
class StubContact : public ContactModel {
 public:
  StubContact(const char* name, ContactPhases phases, ContactStepBound bound, ContactLedger l)
      : ContactModel(name, phases), bound_(bound), given_(std::move(l)) {}
  void begin_step(const State&, double) override { ++begun; }
  void add_forces(State& s) override { s.f[0] += Vec3(1.0, 2.0, 3.0); }
  void correct(State& s, double) override { s.v[0] = 2.0 * s.v[0] + Vec3::UnitX(); }
  void end_step(const State&, double) override { ledger_ = given_; }
  ContactStepBound step_bound(const State&, double) const override { return bound_; }
  double corrected_elements_stable_dt() const override {
    return std::numeric_limits<double>::infinity();
  }
  void add_held_impulses(std::vector<HeldImpulse>& per_body) const override {
    per_body[0].impulse += Vec3::UnitZ();
  }
  int begun = 0;

 private:
  ContactStepBound bound_;
  ContactLedger given_;
};

State one_node_state() {
  State s;
  s.x = s.X = s.v = s.a = s.f = {Vec3::Zero()};
  return s;
}

std::unique_ptr<ContactModel> stub(const char* name, ContactPhases phases, double stiffness_dt,
                                   double kinematic_dt, ContactLedger ledger = {}) {
  return std::make_unique<StubContact>(name, phases, ContactStepBound{stiffness_dt, kinematic_dt},
                                       std::move(ledger));
}

}  // namespace

TEST_CASE("contact set: forces sum and corrections act in member order", "[contact]") {
  std::vector<std::unique_ptr<ContactModel>> members;
  members.push_back(stub("a", kForcePhases, 1.0, 5.0));
  members.push_back(stub("b", kCorrectionPhases, 2.0, 3.0));
  members.push_back(stub("c", kCorrectionPhases, std::numeric_limits<double>::infinity(),
                         std::numeric_limits<double>::infinity()));
  ContactSet set(std::move(members));
  CHECK(set.name() == "a + b + c");
  CHECK(set.phases().adds_forces);
  CHECK(set.phases().corrects);

  State s = one_node_state();
  set.begin_step(s, 1.0);
  for (const auto& m : set.members()) CHECK(static_cast<StubContact&>(*m).begun == 1);
  set.add_forces(s);  // only "a" adds forces
  CHECK(s.f[0] == Vec3(1.0, 2.0, 3.0));
  set.correct(s, 1.0);  // "b" then "c": v -> 2 v + e_x twice, from 0: e_x, then 3 e_x
  CHECK(s.v[0] == Vec3(3.0, 0.0, 0.0));
  std::vector<HeldImpulse> held(1);
  set.add_held_impulses(held);
  CHECK(held[0].impulse == Vec3(0.0, 0.0, 3.0));
}

TEST_CASE("contact set: stiffness steps combine in inverse squares, kinematic steps by minimum",
          "[contact]") {
  std::vector<std::unique_ptr<ContactModel>> members;
  members.push_back(stub("a", kForcePhases, 3.0, 5.0));
  members.push_back(stub("b", kForcePhases, 4.0, 2.0));
  members.push_back(stub("c", kCorrectionPhases, std::numeric_limits<double>::infinity(),
                         std::numeric_limits<double>::infinity()));
  const ContactSet set(std::move(members));
  const ContactStepBound b =
      set.step_bound(one_node_state(), std::numeric_limits<double>::infinity());
  // 1/dt^2 = 1/9 + 1/16 = 25/144: dt = 12/5 exactly (two springs on one mass: omega^2 adds).
  CHECK(b.stiffness_dt == Approx(2.4).epsilon(1e-15));
  CHECK(b.kinematic_dt == 2.0);
}

TEST_CASE("contact set: the ledger sums the members' and names the one that failed", "[contact]") {
  std::vector<std::unique_ptr<ContactModel>> members;
  members.push_back(
      stub("a", kForcePhases, 1.0, 1.0, {.work = 1.5, .injected_energy = 0.25, .failure = ""}));
  members.push_back(stub("b", kCorrectionPhases, 1.0, 1.0,
                         {.work = -0.5, .injected_energy = 0.5, .failure = "x"}));
  ContactSet set(std::move(members));
  set.end_step(one_node_state(), 1.0);
  CHECK(set.ledger().work == 1.0);
  CHECK(set.ledger().injected_energy == 0.75);
  CHECK(set.ledger().failure == "b: x");
}

TEST_CASE("contact set: refuses an empty list", "[contact]") {
  CHECK_THROWS_AS(ContactSet({}), std::invalid_argument);
}
