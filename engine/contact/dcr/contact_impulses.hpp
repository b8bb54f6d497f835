// Velocity-level contact solve of the DCR (docs/contact-method.md §1.3-1.4): non-negative normal
// impulses and Coulomb friction impulses of all contacts of a step, iterated together.
//
// Each contact k has a normal row and two tangential rows on its four nodes a:
//   normal:     rate_n = sum_a grad_a g . v_a >= target  (target <= 0: the approach allowed by
//               the remaining gap, -(g - g_sep) / dt; 0 for a contact that is closed),
//               impulse lambda_n >= 0 along M^-1 grad g;
//   tangential: u_t = sum_a beta_a (t_i . v_a), the relative tangential velocity of the two
//               contact points (beta_a: the contact-point weights, sum_a beta_a = 0), driven to 0
//               by lambda_t (2 components) inside the Coulomb disc |lambda_t| <= mu S lambda_n
//               (S lambda_n is the normal impulse in N s).
// Sweeps are projected symmetric Gauss-Seidel: the rows are visited in a given order (the
// caller's, fixed by the geometry so that the result does not depend on node numbering or search
// order), forward then backward; each row's update is computed from the current velocities and
// applied at once to its four nodes. Every update is along a direction whose mass-weighted sum
// vanishes, so linear momentum is exact; friction opposes the tangential velocity it acts on,
// so it only dissipates.
//
// Warm start (docs/hard-scenes.md, "Resting contact"): a contact held over consecutive steps
// (the same four nodes) starts from the impulses it carried at the end of the last step,
// applied to the velocities before the first sweep (the tangential impulse re-expressed in the
// new tangent basis and put back on the Coulomb disc). A resting contact needs nearly the same
// impulse every step (m g dt under gravity), so its solve starts next to its solution and meets
// the tolerance in a few sweeps instead of running to the cap. The sweeps are the same projected
// Gauss-Seidel from any start: the warm start changes where they begin, not what they solve.
#pragma once

#include <array>
#include <utility>
#include <vector>

#include "engine/contact/dcr/contact_row.hpp"
#include "engine/contact/dcr/patch_solve.hpp"
#include "engine/contact/dcr/rigid_partners.hpp"
#include "engine/core/types.hpp"

namespace ccm::dcr {

// What a row's updates divide by, divided once per solve: 1 / W_n, 1 / W_t (0 when W_t = 0) and
// W_n / S, the contact points' velocity change per unit normal multiplier; and the change of the
// contact points' relative velocity per unit normal multiplier, sum_a beta_a m_a^-1 grad_a g.
struct RowInverse {
  double W_n = 0.0, W_t = 0.0, change_n = 0.0;
  Vec3 slip_per_normal = Vec3::Zero();
};

struct ImpulseSettings {
  double friction = 0.0;        // Coulomb mu
  int max_iterations = 100;     // Gauss-Seidel sweeps
  double tolerance = 1e-9;      // stop when no row changes a velocity by more than this x v_ref
  bool warm_start = true;       // start held contacts from the last step's impulses
  double velocity_floor = 0.0;  // ... or by more than this [m/s], whichever limit is larger
  // Without friction, every this many sweeps without convergence the patches' normal rows are
  // solved directly (patch_solve.hpp); 0: never.
  int direct_after = 10;
};

struct ImpulseSolve {
  int sweeps = 0;
  bool converged = true;  // false: stopped at max_iterations with a row still changing
};

class ContactImpulses {
 public:
  // Solves the rows, visited in `order` (a permutation of their indices), against the
  // velocities v (indexed by global node id; only the rows' nodes are read and written) and
  // returns the number of sweeps made and whether the last one met the tolerance.
  // With free rigid bodies among the held nodes (partners not empty; rigid_partners.hpp), rows on
  // their nodes read and update the bodies (x: the positions the rows were made at) and add
  // their mobility to W_n and W_t; the bodies' velocities in `partners` are the solve's result.
  ImpulseSolve solve(std::vector<ContactRow>& rows, const std::vector<int>& order,
                     const std::vector<double>& inv_m, std::vector<Vec3>& v,
                     const ImpulseSettings& settings, RigidPartners* partners = nullptr,
                     const std::vector<Vec3>* x = nullptr);
  // Rows of the last solve that started from a remembered impulse (diagnostics).
  int warm_started() const { return warm_started_; }

 private:
  // The impulses a contact ended the last step with, keyed by its four nodes.
  struct Remembered {
    std::array<int, 4> nodes{};
    double lambda_n = 0.0;
    Vec3 tangential = Vec3::Zero();  // lambda_t1 t1 + lambda_t2 t2 [N s]
  };
  void warm_start(std::vector<ContactRow>& rows, const std::vector<double>& inv_m,
                  std::vector<Vec3>& v, double friction, bool same_rows);
  // The rows' parts on free rigid bodies (none without partners), their mobility added to the
  // rows, and the rows of each body.
  void attach_rigid(std::vector<ContactRow>& rows, const std::vector<Vec3>& x);
  void mark_body_rows_dirty(size_t row);
  void solve_patches(std::vector<ContactRow>& rows, const std::vector<double>& inv_m,
                     std::vector<Vec3>& v, double limit);
  RigidPartners* partners_ = nullptr;        // of the current solve, or null
  std::vector<int> rigid_index_;             // per row: its entry in rigid_parts_, or -1
  std::vector<RigidRowPart> rigid_parts_;    // rows with nodes of free rigid bodies
  std::vector<std::vector<int>> body_rows_;  // per partner: its rows
  void remember(const std::vector<ContactRow>& rows);
  bool same_rows(const std::vector<ContactRow>& rows) const;
  void link_rows(const std::vector<ContactRow>& rows, bool same);
  void mark_neighbours_dirty(size_t row);
  void remember_velocities(const ContactRow& r, const std::vector<Vec3>& v);
  double largest_change(const std::vector<Vec3>& v) const;
  std::vector<long> stamp_;                  // per node: the sweep (epoch_) that saved its velocity
  long epoch_ = 0;                           // sweeps made by this solver, over all solves
  std::vector<std::pair<int, Vec3>> start_;  // (node, velocity at the start of the sweep)
  std::vector<std::pair<int, int>> entries_;  // (node, row), sorted
  std::vector<std::pair<int, int>> ranges_;   // per row and node: its entries [first, last)
  std::vector<std::array<int, 4>> linked_;    // the rows' nodes that entries_ and ranges_ are of
  std::vector<char> dirty_;                   // per row: a neighbour changed since its last visit
  std::vector<RowInverse> inverse_;           // per row, for the solve's sweeps
  long visits_ = 0;                           // row updates made by the last solve
  std::vector<Remembered> last_;     // per row of the last solve (its rows' nodes: linked_)
  std::vector<Remembered> pushing_;  // scratch: those of last_ with lambda_n > 0, by nodes
  int warm_started_ = 0;
  PatchSolve patches_;
  std::vector<char> held_;  // per row: on a free rigid body (the patch solve leaves it)
};

}  // namespace ccm::dcr
