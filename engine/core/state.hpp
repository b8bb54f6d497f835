// The state of an explicit run: the nodes' arrays (structure-of-arrays, contiguous) and the
// rigid bodies' poses and velocities (engine/body/; their nodes follow them).
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "engine/core/types.hpp"

namespace ccm {

// One rigid body as the step leaves it (written by engine/body/rigid_bodies.hpp).
struct RigidState {
  int body = 0;                                                  // index into the mesh's bodies
  Vec3 center = Vec3::Zero();                                    // centre of mass [m]
  Vec3 reference_center = Vec3::Zero();                          // ... at t = 0 [m]
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();  // since the reference
  Vec3 velocity = Vec3::Zero();                                  // of the centre of mass [m/s]
  Vec3 angular_velocity = Vec3::Zero();                          // world axes [rad/s]
  double kinetic_energy = 0.0;                                   // [J]
  // Momentum and angular momentum (about the centre of mass) the contact has given the body
  // since t = 0 [N s], [N m s]: forces on its nodes and impulses on it alike.
  Vec3 contact_impulse = Vec3::Zero();
  Vec3 contact_angular_impulse = Vec3::Zero();
  // Its mobility, for a contact model that solves with it: 1/m and I^-1 in world axes about
  // `pivot`, which moves at `pivot_velocity`. A free body: its centre of mass. A pinned one: 1/m
  // = 0 and I^-1 = e e^T / J about a point of the pin (docs/rigid-bodies.md, "Pinned"). Both zero
  // for a fixed or prescribed body (infinitely heavy).
  double inverse_mass = 0.0;
  Mat3 inverse_inertia = Mat3::Zero();
  Vec3 pivot = Vec3::Zero();
  Vec3 pivot_velocity = Vec3::Zero();
  bool mobile() const { return inverse_mass > 0.0 || !inverse_inertia.isZero(0.0); }
};

struct State {
  double t = 0.0;
  std::vector<Vec3> X;  // reference positions
  std::vector<Vec3> x;  // current positions (u = x - X)
  std::vector<Vec3> v;  // velocities
  std::vector<Vec3> a;  // accelerations
  std::vector<Vec3> f;  // total nodal force of the last evaluation (scratch)
  std::vector<double> m_lumped;
  std::vector<double> inv_m;
  std::vector<RigidState> rigid;  // one per rigid body, in the model's order

  int n_nodes() const { return static_cast<int>(x.size()); }
};

}  // namespace ccm
