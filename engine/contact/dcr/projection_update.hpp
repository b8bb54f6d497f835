// What a position projection changes in the elements around the moved nodes: the stored energy
// (thesis eq. 2.21, made exact) and the nodal forces, so the step goes on from a consistent
// state.
//
// The DCR projection moves contact nodes from x to x~ after the internal forces were evaluated
// at x. Left alone, the velocity correction v_{n+1} = v* + dt/2 a and the next predictor would
// use forces of a configuration the body is no longer in, and the energy the projection puts in
// would be known only to first order, (f_int - f_ex) . (x - x~) (eq. 2.21), which is wrong where
// the moved node belongs to a stiff body: its 1/2 dx^T K dx dominates (a sphere 1e6 times
// stiffer than what it hits is locally deformed by the mass-weighted push-back). So, over the
// elements e around the moved nodes,
//   dQ = sum_e V0_e [W(F_e(x~)) - W(F_e(x))],    df_i = sum_e [f_e,i(x~) - f_e,i(x)],
// with f_e,a = -V0 P(F_e) grad N_a (eq. 2.1 / 2.3), the same element force as the kernel's, and
// a_i += df_i / m_i. The energy the step then carries changes by
//   dE = dQ + dt/2 sum_i v*_i . df_i,
// the second term being the change of the leapfrog kinetic energy 1/2 m (v_{n+1}^2 - dt^2/4 a^2)
// = 1/2 m v* . (v* + dt a) that the monitor measures (v_{n+1} = v* + dt/2 a).
//
// A body with the averaged-nodal-pressure tet (docs/elements.md) keeps W_e with lambda = 0 here
// (its element part, eq. NP.2); the nodal volumetric part, whose forces reach one ring further,
// is NodalPressureUpdate's (nodal_pressure_update.hpp).
#pragma once

#include <limits>
#include <span>
#include <vector>

#include "engine/contact/dcr/nodal_pressure_update.hpp"
#include "engine/contact/dcr/node_elements.hpp"
#include "engine/core/state.hpp"
#include "engine/core/types.hpp"
#include "engine/element/tet4.hpp"
#include "engine/material/material.hpp"
#include "engine/mesh/model_mesh.hpp"

namespace ccm::dcr {

class ProjectionUpdate {
 public:
  // Only the elements around `movable` nodes (the contact surfaces) are prepared.
  ProjectionUpdate(const ModelMesh& mesh, std::span<const int> movable);

  struct EnergyChange {
    double stored = 0.0;   // dQ [J]
    double kinetic = 0.0;  // dK [J]
    double total() const { return stored + kinetic; }
    // The smallest stable step of the re-evaluated elements at their new positions
    // (element_stable_dt; infinite when none). The structure's step was measured before the
    // projection moved their nodes: a projection that squeezes a thin wall between two contacts
    // shortens it (to 0.58 of the measured one in the crushed pipe of docs/hard-scenes.md), and
    // the next step must not exceed it. For a nodal-pressure body this is the plain tet's bound at
    // the element's own J (the kernel's next evaluation applies the body's nodal one).
    double stable_dt = std::numeric_limits<double>::infinity();
    // The largest move of a node by the projection over the height (characteristic_length, at
    // the new positions) of a re-evaluated element around it; 0 when nothing moved. The contact
    // bounds the next step with it (DcrContact::step_bound, docs/time-step.md).
    double jump_ratio = 0.0;
  };
  // The nodes `moved` (unique) went from `before` (same order) to their positions in s.x: adds
  // the force change divided by the node's mass into s.a (inv_m: 1/m, 0 for fixed nodes) and
  // returns dQ and dK for the step dt, and the stable step of the elements around them.
  EnergyChange apply(std::span<const int> moved, std::span<const Vec3> before, State& s,
                     std::span<const double> inv_m, double dt);
  // The nodes of the plain-tet elements apply() re-evaluates for `moved` (repeats possible): what
  // it reads and writes besides the moved nodes. (A nodal-pressure body's update reaches one ring
  // further; a partitioned run, the only user, refuses such bodies.)
  std::vector<int> element_nodes(std::span<const int> moved) const;

 private:
  struct Element {
    Tet nodes;
    TetReference reference;
    MaterialModel model;
    Lame lame;          // of its energy (lambda = 0 for the nodal-pressure tet)
    Lame stiffness;     // the body's, for its stable step
    double rho0 = 0.0;  // reference density
  };
  // V0 W(F) of e, and its nodal forces added into f[4] with the given sign.
  double evaluate(const Element& e, const Vec3 (&x)[4], double sign, Vec3 (&f)[4]) const;

  NodeElements around_;  // the prepared elements at each movable node
  std::vector<Element> elements_;
  std::vector<int> stamp_;         // per prepared element: the last apply() that counted it
  std::vector<int> before_index_;  // per node: its index in `before` during apply(), else -1
  int epoch_ = 0;
  NodalPressureUpdate nodal_pressure_;
};

}  // namespace ccm::dcr
