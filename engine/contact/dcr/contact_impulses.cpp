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

// One row's update from the current velocities, applied to its four nodes; returns the largest
// velocity change of its contact points.
double update_row(ContactRow& r, const std::vector<double>& inv_m, std::vector<Vec3>& v,
                  double mu) {
  if (!(r.W_n > 0.0)) return 0.0;
  // Normal: lambda_n >= 0, complementary to rate_n >= target.
  const double lambda_n = std::max(0.0, r.lambda_n + (r.target - normal_rate(r, v)) / r.W_n);
  const double d_n = lambda_n - r.lambda_n;
  r.lambda_n = lambda_n;
  for (int a = 0; a < 4; ++a) {
    const auto i = static_cast<size_t>(r.nodes[a]);
    v[i] += inv_m[i] * d_n * r.grad[a];
  }
  double change = std::abs(d_n) * r.W_n / r.S;
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
    const double d_t1 = l1 - r.lambda_t1, d_t2 = l2 - r.lambda_t2;
    r.lambda_t1 = l1;
    r.lambda_t2 = l2;
    const Vec3 tangential = d_t1 * r.t1 + d_t2 * r.t2;
    for (int a = 0; a < 4; ++a) {
      const auto i = static_cast<size_t>(r.nodes[a]);
      v[i] += inv_m[i] * r.beta[a] * tangential;
    }
    change = std::max(change, std::hypot(d_t1, d_t2) * r.W_t);
  }
  return change;
}

}  // namespace

ImpulseSolve ContactImpulses::solve(std::vector<ContactRow>& rows, const std::vector<int>& order,
                           const std::vector<double>& inv_m, std::vector<Vec3>& v,
                           const ImpulseSettings& settings) {
  // Reference speed: the fastest contact node (a solve that moves no node by more than
  // tolerance x v_ref has converged).
  double v_ref = 0.0;
  for (const ContactRow& r : rows)
    for (int n : r.nodes) v_ref = std::max(v_ref, v[static_cast<size_t>(n)].norm());
  const double limit = settings.tolerance * std::max(v_ref, 1e-300);
  ImpulseSolve out{0, rows.empty()};
  while (out.sweeps < settings.max_iterations) {
    double worst = 0.0;
    const int sweep = out.sweeps;
    const bool forward = sweep % 2 == 0;
    for (size_t j = 0; j < order.size(); ++j) {
      ContactRow& r = rows[static_cast<size_t>(order[forward ? j : order.size() - 1 - j])];
      worst = std::max(worst, update_row(r, inv_m, v, settings.friction));
    }
    ++out.sweeps;
    if (worst <= limit) {
      out.converged = true;
      break;
    }
  }
  return out;
}

}  // namespace ccm::dcr
