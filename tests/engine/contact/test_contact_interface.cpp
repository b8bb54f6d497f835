// The contact interface cannot be half-implemented: ContactModel is abstract (its six pure
// virtual methods), and every concrete model and wrapper implements all of them
// (an abstract class cannot be named here as constructible). A model that leaves one out fails
// these static assertions at compile time.
#include <catch2/catch.hpp>
#include <type_traits>

#include "engine/contact/contact_model.hpp"
#include "engine/contact/contact_set.hpp"
#include "engine/contact/dcr/dcr_contact.hpp"
#include "engine/contact/penalty/rigid_surface_penalty.hpp"
#include "engine/contact/rigid_sphere_penalty.hpp"
#include "engine/distributed/replicated_contact.hpp"
#include "io/fields/contact_impulse_probe.hpp"

namespace {

using namespace ccm;

static_assert(std::is_abstract_v<ContactModel>);
static_assert(!std::is_abstract_v<dcr::DcrContact>);
static_assert(!std::is_abstract_v<RigidSpherePenalty>);
static_assert(!std::is_abstract_v<fields::ContactImpulseProbe>);
static_assert(!std::is_abstract_v<distributed::ReplicatedContact>);
static_assert(!std::is_abstract_v<RigidSurfacePenalty>);
static_assert(!std::is_abstract_v<ContactSet>);
// The name and the ledger are base-class data: not virtual, nothing to forward.
static_assert(std::is_same_v<decltype(&ContactModel::ledger),
                             const ContactLedger& (ContactModel::*)() const>);

// A model that implements four of the six is abstract.
struct FourOfFive : ContactModel {
  FourOfFive() : ContactModel("four", kForcePhases) {}
  void begin_step(const State&, double) override {}
  void add_forces(State&) override {}
  void correct(State&, double) override {}
  void end_step(const State&, double) override {}
};
static_assert(std::is_abstract_v<FourOfFive>);

}  // namespace

TEST_CASE("contact interface: a model's bound carries no safety factor by default", "[contact]") {
  // The default bound is no bound at all: a model that adds nothing does not limit the step.
  const ContactStepBound none;
  CHECK(std::isinf(none.stiffness_dt));
  CHECK(std::isinf(none.kinematic_dt));
}
