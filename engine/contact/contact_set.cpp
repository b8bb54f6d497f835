#include "engine/contact/contact_set.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace ccm {

namespace {

std::string joined_names(const std::vector<std::unique_ptr<ContactModel>>& members) {
  if (members.empty()) throw std::invalid_argument("a contact set needs at least one model");
  std::string name;
  for (const auto& m : members) {
    if (!m) throw std::invalid_argument("a contact set's model is missing");
    name += (name.empty() ? "" : " + ") + m->name();
  }
  return name;
}

ContactPhases united_phases(const std::vector<std::unique_ptr<ContactModel>>& members) {
  ContactPhases p;
  for (const auto& m : members) {
    p.adds_forces = p.adds_forces || m->phases().adds_forces;
    p.corrects = p.corrects || m->phases().corrects;
  }
  return p;
}

}  // namespace

ContactSet::ContactSet(std::vector<std::unique_ptr<ContactModel>> members)
    : ContactModel(joined_names(members), united_phases(members)), members_(std::move(members)) {}

void ContactSet::begin_step(const State& state, double dt) {
  for (const auto& m : members_) m->begin_step(state, dt);
}

void ContactSet::add_forces(State& state) {
  for (const auto& m : members_)
    if (m->phases().adds_forces) m->add_forces(state);
}

void ContactSet::correct(State& state, double dt) {
  for (const auto& m : members_)
    if (m->phases().corrects) m->correct(state, dt);
}

void ContactSet::end_step(const State& state, double dt) {
  ledger_ = {};
  for (const auto& m : members_) {
    m->end_step(state, dt);
    const ContactLedger& l = m->ledger();
    ledger_.work += l.work;
    ledger_.injected_energy += l.injected_energy;
    ledger_.touching = ledger_.touching || l.touching;
    if (ledger_.failure.empty() && !l.failure.empty())
      ledger_.failure = m->name() + ": " + l.failure;
  }
}

// 1/dt^2 = sum_i 1/dt_i^2 for the stiffness steps; the smallest kinematic step (header).
ContactStepBound ContactSet::step_bound(const State& state, double ceiling) const {
  ContactStepBound bound;
  double inverse_square = 0.0;
  for (const auto& m : members_) {
    const ContactStepBound b = m->step_bound(state, ceiling);
    if (std::isfinite(b.stiffness_dt)) inverse_square += 1.0 / (b.stiffness_dt * b.stiffness_dt);
    bound.kinematic_dt = std::min(bound.kinematic_dt, b.kinematic_dt);
  }
  if (inverse_square > 0.0) bound.stiffness_dt = 1.0 / std::sqrt(inverse_square);
  return bound;
}

double ContactSet::corrected_elements_stable_dt() const {
  double dt = std::numeric_limits<double>::infinity();
  for (const auto& m : members_) dt = std::min(dt, m->corrected_elements_stable_dt());
  return dt;
}

void ContactSet::use_replica_team(ReplicaTeam& team) {
  for (const auto& m : members_) m->use_replica_team(team);
}

void ContactSet::add_held_impulses(std::vector<HeldImpulse>& per_body) const {
  for (const auto& m : members_) m->add_held_impulses(per_body);
}

}  // namespace ccm
