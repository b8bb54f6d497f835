#include "engine/contact/dcr/contact_impulses.hpp"

#include <algorithm>
#include <cmath>

namespace ccm::dcr {
namespace {

double normal_rate(const ContactRow& r, const std::vector<Vec3>& v) {
  double rate = 0.0;  // dg/dt = grad g . v
  for (int a = 0; a < 4; ++a) rate += r.grad[a].dot(v[static_cast<size_t>(r.nodes[a])]);
  return rate;
}

// Relative tangential velocity of the two contact points, in the (t1, t2) basis.
std::array<double, 2> tangential_velocity(const ContactRow& r, const std::vector<Vec3>& v) {
  Vec3 u = Vec3::Zero();
  for (int a = 0; a < 4; ++a) u += r.beta[a] * v[static_cast<size_t>(r.nodes[a])];
  return {u.dot(r.t1), u.dot(r.t2)};
}

}  // namespace

double ContactImpulses::propose(ContactRow& r, const std::vector<Vec3>& v, double mu, size_t k) {
  auto& [d_n, d_t1, d_t2] = step_[k];
  d_n = d_t1 = d_t2 = 0.0;
  if (!(r.W_n > 0.0)) return 0.0;
  // Normal: lambda_n >= 0, complementary to rate_n >= target.
  const double lambda_n = std::max(0.0, r.lambda_n + (r.target - normal_rate(r, v)) / r.W_n);
  d_n = lambda_n - r.lambda_n;
  double change = std::abs(d_n) * r.W_n / r.S;  // velocity change of the contact points
  if (mu > 0.0 && r.W_t > 0.0) {
    // Tangential: the impulse that stops the sliding, projected onto the Coulomb disc of the
    // updated normal impulse.
    const auto u = tangential_velocity(r, v);
    double l1 = r.lambda_t1 - u[0] / r.W_t, l2 = r.lambda_t2 - u[1] / r.W_t;
    const double bound = mu * r.S * lambda_n, norm = std::hypot(l1, l2);
    if (norm > bound) {
      l1 *= bound / norm;
      l2 *= bound / norm;
    }
    d_t1 = l1 - r.lambda_t1;
    d_t2 = l2 - r.lambda_t2;
    change = std::max(change, std::hypot(d_t1, d_t2) * r.W_t);
  }
  return change;
}

// Relaxed application: each row's changes divided by the most proposing rows at any of its
// nodes, then applied whole to its four nodes and accumulated.
void ContactImpulses::apply(const std::vector<ContactRow>& rows, const std::vector<double>& inv_m,
                            std::vector<Vec3>& v) {
  auto proposes = [&](size_t k) { return step_[k] != std::array<double, 3>{0.0, 0.0, 0.0}; };
  for (size_t k = 0; k < rows.size(); ++k)
    if (proposes(k))
      for (int n : rows[k].nodes) ++count_[static_cast<size_t>(n)];
  for (size_t k = 0; k < rows.size(); ++k) {
    if (!proposes(k)) continue;
    const ContactRow& r = rows[k];
    int shared = 1;
    for (int n : r.nodes) shared = std::max(shared, count_[static_cast<size_t>(n)]);
    for (double& d : step_[k]) d /= shared;
    const auto [d_n, d_t1, d_t2] = step_[k];
    const Vec3 tangential = d_t1 * r.t1 + d_t2 * r.t2;
    for (int a = 0; a < 4; ++a) {
      const auto i = static_cast<size_t>(r.nodes[a]);
      v[i] += inv_m[i] * (d_n * r.grad[a] + r.beta[a] * tangential);
    }
  }
  for (const ContactRow& r : rows)
    for (int n : r.nodes) count_[static_cast<size_t>(n)] = 0;
}

int ContactImpulses::solve(std::vector<ContactRow>& rows, const std::vector<double>& inv_m,
                           std::vector<Vec3>& v, const ImpulseSettings& settings) {
  step_.resize(rows.size());
  if (count_.size() < v.size()) count_.assign(v.size(), 0);
  // Reference speed: the fastest contact node (a solve that moves no node by more than
  // tolerance x v_ref has converged).
  double v_ref = 0.0;
  for (const ContactRow& r : rows)
    for (int n : r.nodes) v_ref = std::max(v_ref, v[static_cast<size_t>(n)].norm());
  const double limit = settings.tolerance * std::max(v_ref, 1e-300);
  int sweep = 0;
  while (sweep < settings.max_iterations) {
    double worst = 0.0;
    for (size_t k = 0; k < rows.size(); ++k)
      worst = std::max(worst, propose(rows[k], v, settings.friction, k));
    if (worst <= limit) break;
    apply(rows, inv_m, v);
    for (size_t k = 0; k < rows.size(); ++k) {
      rows[k].lambda_n += step_[k][0];
      rows[k].lambda_t1 += step_[k][1];
      rows[k].lambda_t2 += step_[k][2];
    }
    ++sweep;
  }
  return sweep;
}

}  // namespace ccm::dcr
