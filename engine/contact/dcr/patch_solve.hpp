// A direct solve of the normal rows of each contact patch: what the Gauss-Seidel sweeps of
// contact_impulses.hpp reach when they converge, found at once for a patch whose sweeps stall
// (docs/hard-scenes.md, "The velocity solves at their cap").
//
// The rows of a patch are those that push or are violated (by more than S tol, below), joined
// through shared nodes. With every tangential impulse and every other row held, their normal
// multipliers lambda solve the linear complementarity problem
//   w = A lambda + r0 - target >= 0,   lambda >= 0,   w_i lambda_i = 0                    (DP.1)
// with A_ij = sum_n m_n^-1 grad_i(n) . grad_j(n) the Delassus matrix of the normal rows (n over
// the nodes rows i and j share; A_ii = W_n) and r0 the rows' normal rates with the patch's normal
// impulses taken out. The active-set method: with S the rows that push,
//   (A_SS + eps diag(A_SS)) lambda_S = target_S - r0_S,   lambda = 0 off S                (DP.2)
// A row is infeasible when it is in S with a negative lambda, or off S with w below -S tol (S tol:
// the rate by which its contact point's speed is off by the sweeps' tolerance tol;
// contact_row.hpp). Block principal pivoting (Judice & Pires 1994): every infeasible row changes
// side at once while their number falls (or for kPatience rounds without), then only the last one
// (Murty's rule, finite for a positive definite matrix), at most kRounds rounds. eps = 1e-4 while
// pivoting: the two-way node-face rows of one patch are nearly one constraint twice, and with less
// the pair's split swings and the pivoting cycles (Hertz h320, 7 December 2026: 1e-9 left 28 % of
// the patches unsettled after 30 rounds and 1e-6 18 %; 1e-4 0.1 %, 3.6 rounds a patch). Once S has
// settled it is solved again with eps = 1e-9 and iterative refinement with that factor M:
//   x <- x + M^-1 (b - A_SS x),   up to three times while the residual falls,              (DP.3)
// which lands on A_SS's own solution where A_SS is regular (a column of 60 masses, cond ~1e6,
// on its closed form to 1e-12, where eps = 1e-4 alone is 1e-2 off); that result is kept when S is
// still feasible with it, else the pivoting's (its rates off by eps of the row's own change).
// The result is kept only if the active set settled and the patch's impulses, applied from none,
// do not add kinetic energy:
//   lambda . r0 + lambda . A lambda / 2 <= 0                                               (DP.4)
// (a contact only dissipates). Else the sweeps go on from where they were. The update of each
// row is along m^-1 grad, whose mass-weighted sum vanishes: linear momentum stays exact.
#pragma once

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <utility>
#include <vector>

#include "engine/contact/dcr/contact_row.hpp"
#include "engine/core/types.hpp"

namespace ccm::dcr {

class PatchSolve {
 public:
  // rows and v as ContactImpulses::solve's; entries: (node, row) of every row's four nodes,
  // sorted; held: per row, 1 for a row this solve leaves as it is (on a free rigid body);
  // tolerance: the contact points' speed tolerance [m/s] (the sweeps'). Updates the rows' lambda_n
  // and v (a patch whose result fails DP.4 is left as it was).
  void solve(std::vector<ContactRow>& rows, const std::vector<double>& inv_m, std::vector<Vec3>& v,
             const std::vector<std::pair<int, int>>& entries, const std::vector<char>& held,
             double tolerance);

 private:
  void solve_patch(std::vector<ContactRow>& rows, const std::vector<int>& patch,
                   const std::vector<double>& inv_m, std::vector<Vec3>& v,
                   const std::vector<std::pair<int, int>>& entries, double tolerance);
  std::vector<double> rate_;     // per row: its normal rate at the solve's start
  std::vector<char> candidate_;  // per row: pushes, or is violated
  std::vector<int> parent_;      // union-find over the rows
  std::vector<int> local_;       // per row: its index in the current patch, or -1
  Eigen::SparseMatrix<double> delassus(const std::vector<ContactRow>& rows,
                                       const std::vector<int>& patch,
                                       const std::vector<double>& inv_m,
                                       const std::vector<std::pair<int, int>>& entries);
  static bool solve_active(const Eigen::SparseMatrix<double>& A, const std::vector<char>& active,
                           const Eigen::VectorXd& b, double eps, int refinements,
                           Eigen::VectorXd& lambda);
};

}  // namespace ccm::dcr
