// What a run knows of its rigid bodies before it starts (part of the Model): which body of the
// mesh each one is, how it may move, its mass properties and its initial or prescribed motion.
// A rigid body keeps its mesh (its nodes carry its surface for contact, loads, histories and
// fields) but its elements are left out of the step: no internal forces, no stable-step limit
// (docs/rigid-bodies.md).
#pragma once

#include <array>
#include <string_view>

#include "engine/body/mass_properties.hpp"
#include "engine/body/pinned_motion.hpp"
#include "engine/core/time_table.hpp"
#include "engine/core/types.hpp"

namespace ccm {

enum class RigidMotion {
  free,        // six degrees of freedom under its loads, gravity and contact
  fixed,       // never moves
  prescribed,  // its centre of mass and rotation follow given velocity histories
  pinned,      // turns about a fixed pin axis under its loads, gravity and contact
};
std::string_view to_string(RigidMotion m);

struct RigidBodyModel {
  int body = 0;  // index into ModelMesh::bodies
  RigidMotion motion = RigidMotion::free;
  MassProperties mass;                   // about the centre of mass, in the reference configuration
  Vec3 velocity = Vec3::Zero();          // free: initial velocity of the centre of mass [m/s]
  Vec3 angular_velocity = Vec3::Zero();  // free, pinned: initial angular velocity, world axes
                                         // [rad/s] (pinned: along the pin's axis)
  RigidPin pin;                          // pinned: the axis and the pin's friction
  // prescribed: velocity of the centre of mass and angular velocity (world axes), each component
  // a piecewise-linear history [m/s], [rad/s].
  std::array<TimeTable, 3> prescribed_velocity{TimeTable({{0.0, 0.0}}), TimeTable({{0.0, 0.0}}),
                                               TimeTable({{0.0, 0.0}})};
  std::array<TimeTable, 3> prescribed_angular_velocity{
      TimeTable({{0.0, 0.0}}), TimeTable({{0.0, 0.0}}), TimeTable({{0.0, 0.0}})};

  // Fixed or prescribed: moved by its driver, whatever acts on it.
  bool kinematic() const {
    return motion == RigidMotion::fixed || motion == RigidMotion::prescribed;
  }
};

}  // namespace ccm

namespace ccm {

struct ModelMesh;

// Marks body `body` of the mesh rigid (before make_model: its elements then stay out of the
// step) and returns its model with mass properties computed from its tets and its material's
// density (mass_properties.hpp). Throws std::invalid_argument when the body's volume is not
// positive.
RigidBodyModel make_rigid(ModelMesh& mesh, int body, RigidMotion motion);

}  // namespace ccm
