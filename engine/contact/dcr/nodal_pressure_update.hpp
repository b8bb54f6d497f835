// The volumetric part of the projection update (projection_update.hpp) for bodies with the
// averaged-nodal-pressure tet (docs/elements.md, eq. NP.1-NP.4).
//
// Such a body stores sum_e V0_e W_e(F_e) + sum_n V0_n U(J_n), U(J) = lambda/2 (ln J)^2,
// J_n = V_n / V0_n, V_n = sum_{e containing n} V_e / 4. ProjectionUpdate takes the element part
// W_e (the Neo-Hookean with lambda = 0) over the elements around the moved nodes; this class the
// nodal part. Moving nodes M changes
//   - V_e of the elements E1 around M, so V_n and p_n = U'(J_n) of their nodes N1 (eq. NP.2-3):
//       dQ_vol = sum_{n in N1} V0_n [U(J_n(x~)) - U(J_n(x))];
//   - the volumetric force f_a = -sum_e pbar_e dV_e/dx_a (eq. NP.4) of every element E2 holding
//     a node of N1 (its mean pressure pbar_e changed), a ring wider than E1:
//       df_a = -sum_{e in E2} [pbar_e(x~) dV_e/dx_a(x~) - pbar_e(x) dV_e/dx_a(x)],
//     where dV_e/dx_a is unchanged outside E1 and only the pressures of N1 change.
#pragma once

#include <span>
#include <vector>

#include "engine/contact/dcr/node_elements.hpp"
#include "engine/core/state.hpp"
#include "engine/core/types.hpp"
#include "engine/mesh/model_mesh.hpp"

namespace ccm::dcr {

class NodalPressureUpdate {
 public:
  // Prepares the nodal-pressure elements within two rings of the `movable` nodes; nothing when
  // no body uses the element.
  NodalPressureUpdate(const ModelMesh& mesh, std::span<const int> movable);

  bool empty() const { return elements_.empty(); }

  // Position of node i before the move (before_index[i] >= 0: before[before_index[i]], else the
  // current s.x[i]). Adds df / m into s.a and returns {dQ_vol, dt/2 sum v . df}, as
  // ProjectionUpdate::apply does for the element part.
  struct Change {
    double stored = 0.0, kinetic = 0.0;
  };
  Change apply(std::span<const int> moved, std::span<const Vec3> before,
               std::span<const int> before_index, State& s, std::span<const double> inv_m,
               double dt);

 private:
  struct NodeValues {
    double p_old = 0.0, p_new = 0.0;
  };
  // The current volume V_e and its gradient (eq. NP.4: dV_e/dx_{c+1} = n_c / 6).
  static double volume(const Vec3 (&x)[4], Vec3 (&dV)[4]);
  struct ElementVolume {
    double old_value = 0.0, new_value = 0.0;
  };
  // V_e before (old) and after (new) the move, for the elements of E2.
  void element_volumes(std::span<const Vec3> before, std::span<const int> before_index,
                       const std::vector<Vec3>& x);
  void mark_rings(std::span<const int> moved);
  Change nodal_energy(std::span<const Vec3> before, std::span<const int> before_index,
                      const std::vector<Vec3>& x);
  void add_force_change(int k, std::span<const Vec3> before, std::span<const int> before_index,
                        State& s, std::span<const double> inv_m, double dt, Change& out) const;

  std::vector<Tet> elements_;  // prepared: every nodal-pressure element within two rings
  NodeElements around_;        // the prepared elements at each node (all of them)
  std::vector<double> V0_node_, lambda_node_;
  std::vector<char> moves_;  // per prepared element: holds a moved node (E1) in this apply()
  std::vector<NodeValues> pressure_;   // per node, valid for the nodes of ring_nodes_
  std::vector<ElementVolume> volume_;  // per prepared element, valid for ring_elements_
  std::vector<int> stamp_node_, stamp_element_;
  std::vector<int> ring_nodes_, ring_elements_;  // N1 and E2 of this apply(), first-seen order
  int epoch_ = 0;
};

}  // namespace ccm::dcr
