// The impulse a contact gave, in one step, to a body whose nodes it holds without moving them
// (fixed nodes, rigid bodies): engine/contact/contact_model.hpp reports it, engine/body/ takes it.
#pragma once

#include "engine/core/types.hpp"

namespace ccm {

// What a constraint-type model's correction gave, in one step, to a body whose nodes it holds
// without moving them (fixed nodes, rigid bodies): the sum of its impulses on the body's nodes
// [N s] and of their moments about the origin [N m s]. A free rigid body takes them as its
// reaction, so that the momentum the contact exchanges is kept exactly.
struct HeldImpulse {
  Vec3 impulse = Vec3::Zero();
  Vec3 moment = Vec3::Zero();
};

}  // namespace ccm
