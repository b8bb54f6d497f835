#include "engine/contact/dcr/patch_solve.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <numeric>

namespace ccm::dcr {
namespace {

constexpr int kRounds = 30;   // active-set rounds per patch (DP.2)
constexpr int kPatience = 3;  // block rounds without fewer infeasible rows, then single pivots
constexpr double kPivotRegularisation = 1e-4;  // eps of DP.2 while the rows are pivoted
constexpr double kRegularisation = 1e-9;       // eps of DP.3, the settled rows' final solve
constexpr int kRefinements = 3;                // of DP.3
constexpr Eigen::Index kDenseRows = 96;        // active sets up to this size: dense LDLT

int root(std::vector<int>& parent, int i) {
  while (parent[static_cast<size_t>(i)] != i)
    i = parent[static_cast<size_t>(i)] =
        parent[static_cast<size_t>(parent[static_cast<size_t>(i)])];
  return i;
}

double normal_rate(const ContactRow& r, const std::vector<Vec3>& v) {
  double rate = 0.0;
  for (int a = 0; a < 4; ++a) rate += r.grad[a].dot(v[static_cast<size_t>(r.nodes[a])]);
  return rate;
}

// Sums by plain loops: GCC 12 warns (a false positive, cmake/Warnings.cmake) in Eigen's AVX-512
// reduction of a dynamic vector, which engine/ does not silence.
double dot(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  double sum = 0.0;
  for (Eigen::Index i = 0; i < a.size(); ++i) sum += a[i] * b[i];
  return sum;
}

int slot_of(const ContactRow& r, int node) {
  for (int a = 0; a < 4; ++a)
    if (r.nodes[a] == node) return a;
  return -1;
}

}  // namespace

void PatchSolve::solve(std::vector<ContactRow>& rows, const std::vector<double>& inv_m,
                       std::vector<Vec3>& v, const std::vector<std::pair<int, int>>& entries,
                       const std::vector<char>& held, double tolerance) {
  const size_t n = rows.size();
  rate_.assign(n, 0.0);
  candidate_.assign(n, 0);
  parent_.resize(n);
  std::iota(parent_.begin(), parent_.end(), 0);
  for (size_t k = 0; k < n; ++k) {
    const ContactRow& r = rows[k];
    if (held[k] || !(r.W_n > 0.0)) continue;
    rate_[k] = normal_rate(r, v);
    candidate_[k] = r.lambda_n > 0.0 || rate_[k] < r.target - tolerance * r.S;
  }
  // Patches: the candidate rows joined through the nodes they share.
  for (size_t e = 0; e < entries.size();) {
    size_t end = e;
    int first = -1;
    for (; end < entries.size() && entries[end].first == entries[e].first; ++end) {
      const int k = entries[end].second;
      if (!candidate_[static_cast<size_t>(k)]) continue;
      if (first < 0)
        first = k;
      else
        parent_[static_cast<size_t>(root(parent_, k))] = root(parent_, first);
    }
    e = end;
  }
  std::vector<std::vector<int>> patches;
  std::vector<int> patch_of(n, -1);
  for (size_t k = 0; k < n; ++k) {
    if (!candidate_[k]) continue;
    const auto r = static_cast<size_t>(root(parent_, static_cast<int>(k)));
    if (patch_of[r] < 0) {
      patch_of[r] = static_cast<int>(patches.size());
      patches.emplace_back();
    }
    patches[static_cast<size_t>(patch_of[r])].push_back(static_cast<int>(k));
  }
  local_.assign(n, -1);
  for (const std::vector<int>& patch : patches) {
    for (size_t i = 0; i < patch.size(); ++i)
      local_[static_cast<size_t>(patch[i])] = static_cast<int>(i);
    solve_patch(rows, patch, inv_m, v, entries, tolerance);
    for (int k : patch) local_[static_cast<size_t>(k)] = -1;
  }
}

// A: over each node the patch's rows share, every pair of them (local_ holds the rows' places).
Eigen::SparseMatrix<double> PatchSolve::delassus(const std::vector<ContactRow>& rows,
                                                 const std::vector<int>& patch,
                                                 const std::vector<double>& inv_m,
                                                 const std::vector<std::pair<int, int>>& entries) {
  std::vector<Eigen::Triplet<double>> terms;
  std::vector<int> at;  // the patch's rows at one node
  for (int k : patch)
    for (int a = 0; a < 4; ++a) {
      const int node = rows[static_cast<size_t>(k)].nodes[a];
      const auto lo =
          std::lower_bound(entries.begin(), entries.end(), std::pair<int, int>{node, -1});
      at.clear();
      for (auto e = lo; e != entries.end() && e->first == node; ++e)
        if (local_[static_cast<size_t>(e->second)] >= 0) at.push_back(e->second);
      if (at.front() != k) continue;  // each node once: from the patch's first row on it
      const double w = inv_m[static_cast<size_t>(node)];
      for (int p : at)
        for (int q : at) {
          const ContactRow& rp = rows[static_cast<size_t>(p)];
          const ContactRow& rq = rows[static_cast<size_t>(q)];
          terms.emplace_back(local_[static_cast<size_t>(p)], local_[static_cast<size_t>(q)],
                             w * rp.grad[slot_of(rp, node)].dot(rq.grad[slot_of(rq, node)]));
        }
    }
  const auto m = static_cast<Eigen::Index>(patch.size());
  Eigen::SparseMatrix<double> A(m, m);
  A.setFromTriplets(terms.begin(), terms.end());
  return A;
}

// DP.2-DP.3 for the active rows: lambda_S (0 off S), or false when the factorisation fails.
bool PatchSolve::solve_active(const Eigen::SparseMatrix<double>& A, const std::vector<char>& active,
                              const Eigen::VectorXd& b, double eps, int refinements,
                              Eigen::VectorXd& lambda) {
  using Matrix = Eigen::SparseMatrix<double>;
  std::vector<Eigen::Index> index(active.size(), -1);
  Eigen::Index s = 0;
  for (size_t i = 0; i < active.size(); ++i)
    if (active[i]) index[i] = s++;
  lambda.setZero();
  if (s == 0) return true;
  std::vector<Eigen::Triplet<double>> sub;
  for (Eigen::Index col = 0; col < A.outerSize(); ++col)
    for (Matrix::InnerIterator it(A, col); it; ++it) {
      const Eigen::Index i = index[static_cast<size_t>(it.row())],
                         j = index[static_cast<size_t>(col)];
      if (i >= 0 && j >= 0) sub.emplace_back(i, j, it.value());
    }
  Matrix A_s(s, s), M(s, s);
  A_s.setFromTriplets(sub.begin(), sub.end());
  M = A_s;
  for (Eigen::Index i = 0; i < s; ++i) M.coeffRef(i, i) *= 1.0 + eps;
  Eigen::VectorXd b_s(s);
  for (size_t i = 0; i < active.size(); ++i)
    if (index[i] >= 0) b_s[index[i]] = b[static_cast<Eigen::Index>(i)];
  // A small active set is factorised dense: the sparse factorisation's ordering (AMD) cost more
  // than the factorisation itself (docs/hard-scenes.md, "Small active sets factorised dense").
  const bool dense = s <= kDenseRows;
  Eigen::LDLT<Eigen::MatrixXd> dense_ldlt;
  Eigen::SimplicialLDLT<Matrix> sparse_ldlt;
  if (dense) {
    dense_ldlt.compute(Eigen::MatrixXd(M));
    if (dense_ldlt.info() != Eigen::Success) return false;
  } else {
    sparse_ldlt.compute(M);
    if (sparse_ldlt.info() != Eigen::Success) return false;
  }
  auto solve = [&](const Eigen::VectorXd& rhs) -> Eigen::VectorXd {
    return dense ? Eigen::VectorXd(dense_ldlt.solve(rhs)) : Eigen::VectorXd(sparse_ldlt.solve(rhs));
  };
  Eigen::VectorXd x = solve(b_s);
  Eigen::VectorXd e = b_s - A_s * x;
  double residual = dot(e, e);
  for (int refine = 0; refine < refinements; ++refine) {  // while it helps
    const Eigen::VectorXd y = x + solve(e);
    const Eigen::VectorXd f = b_s - A_s * y;
    const double r = dot(f, f);
    if (!(r < residual)) break;
    x = y;
    e = f;
    residual = r;
  }
  for (size_t i = 0; i < active.size(); ++i)
    if (index[i] >= 0) lambda[static_cast<Eigen::Index>(i)] = x[index[i]];
  return x.allFinite();
}

// DP.1-DP.2 on one patch (its rows ascending; local_ holds their places in it). The result is
// kept only when it is the patch's solution (no row left violated, the active set settled) and
// the patch's impulses, from none, take energy out (DP.4); else the sweeps go on from where they
// were.
void PatchSolve::solve_patch(std::vector<ContactRow>& rows, const std::vector<int>& patch,
                             const std::vector<double>& inv_m, std::vector<Vec3>& v,
                             const std::vector<std::pair<int, int>>& entries, double tolerance) {
  const Eigen::SparseMatrix<double> A = delassus(rows, patch, inv_m, entries);
  const auto m = static_cast<Eigen::Index>(patch.size());
  // slack: a rate below its target by less moves a contact point by less than the tolerance
  // (a normal update d lambda changes the rate by W_n d lambda and the point's speed by
  // W_n / S d lambda: the rate's tolerance is S times the speed's).
  Eigen::VectorXd lambda0(m), target(m), rate(m), slack(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    const auto k = static_cast<size_t>(patch[static_cast<size_t>(i)]);
    lambda0[i] = rows[k].lambda_n;
    target[i] = rows[k].target;
    rate[i] = rate_[k];
    slack[i] = tolerance * rows[k].S;
  }
  const Eigen::VectorXd r0 = rate - A * lambda0;  // the rates with the patch's impulses out
  std::vector<char> active(patch.size());
  for (Eigen::Index i = 0; i < m; ++i)
    active[static_cast<size_t>(i)] = lambda0[i] > 0.0 || rate[i] < target[i] - slack[i];
  Eigen::VectorXd lambda(m);
  bool settled = false;
  size_t fewest = patch.size() + 1;  // the fewest infeasible rows so far
  int patience = kPatience;
  std::vector<Eigen::Index> infeasible;
  for (int round = 0; round < kRounds && !settled; ++round) {
    if (!solve_active(A, active, target - r0, kPivotRegularisation, 0, lambda)) return;
    const Eigen::VectorXd w = A * lambda + r0 - target;
    infeasible.clear();
    for (Eigen::Index i = 0; i < m; ++i)
      if (active[static_cast<size_t>(i)] ? lambda[i] < 0.0 : w[i] < -slack[i])
        infeasible.push_back(i);
    settled = infeasible.empty();
    // Block pivoting while the infeasible rows become fewer (or for kPatience rounds without),
    // then one row at a time, the last (Murty's rule: finite for a positive definite A).
    if (infeasible.size() < fewest) {
      fewest = infeasible.size();
      patience = kPatience;
    } else if (patience > 0) {
      --patience;
    } else {
      infeasible.erase(infeasible.begin(), infeasible.end() - 1);
    }
    for (Eigen::Index i : infeasible) active[static_cast<size_t>(i)] ^= 1;
  }
  // DP.3: the settled rows again, closely; kept where it leaves them settled.
  Eigen::VectorXd close(m);
  if (settled && solve_active(A, active, target - r0, kRegularisation, kRefinements, close)) {
    const Eigen::VectorXd w = A * close + r0 - target;
    bool feasible = true;
    for (Eigen::Index i = 0; i < m && feasible; ++i)
      feasible = active[static_cast<size_t>(i)] ? close[i] >= 0.0 : w[i] >= -slack[i];
    if (feasible) lambda = close;
  }
  // DP.4: the energy the patch's impulses change, from none: lambda . r0 + lambda A lambda / 2.
  const Eigen::VectorXd A_lambda = A * lambda;
  if (!settled || dot(lambda, r0) + 0.5 * dot(lambda, A_lambda) > 0.0) return;
  for (Eigen::Index i = 0; i < m; ++i) {
    ContactRow& r = rows[static_cast<size_t>(patch[static_cast<size_t>(i)])];
    const double d = lambda[i] - r.lambda_n;
    r.lambda_n = lambda[i];
    for (int a = 0; a < 4; ++a) {
      const auto node = static_cast<size_t>(r.nodes[a]);
      v[node] += inv_m[node] * d * r.grad[a];
    }
  }
}

}  // namespace ccm::dcr
