#include "engine/monitor/stability_monitor.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "engine/monitor/fixed_order_sum.hpp"

namespace ccm {

void EnergyBalance::start(double kinetic, double internal, double floor) {
  initial_ = kinetic + internal;
  scale_ = std::max(std::abs(initial_), floor);
}

double EnergyBalance::update(double kinetic, double internal, double external_work) {
  scale_ = std::max({scale_, std::abs(kinetic), std::abs(internal), std::abs(external_work)});
  const double residual = kinetic + internal - initial_ - external_work;
  last_error_ = scale_ > 0.0 ? std::abs(residual) / scale_ : 0.0;
  if (!std::isfinite(residual)) last_error_ = std::numeric_limits<double>::infinity();
  max_error_ = std::max(max_error_, last_error_);
  return last_error_;
}

double leapfrog_kinetic_energy(const State& s, double dt, int threads, int n_nodes) {
  const double q = 0.25 * dt * dt;
  const int n = n_nodes < 0 ? s.n_nodes() : n_nodes;
  const double ke = fixed_order_sum(n, threads, [&](int node) {
    const auto i = static_cast<size_t>(node);
    return s.m_lumped[i] * (s.v[i].squaredNorm() - q * s.a[i].squaredNorm());
  });
  return 0.5 * ke;
}

std::optional<Instability> check_elements(const InternalForceResult& r, double t) {
  if (r.first_bad_element < 0) return std::nullopt;
  const int e = r.first_bad_element;
  if (!std::isfinite(r.bad_J))
    return Instability{t, fmt::format("non-finite deformation in element {}", e), e, -1};
  return Instability{t, fmt::format("inverted element {}: J = {:.4g}", e, r.bad_J), e, -1};
}

std::optional<Instability> check_finite(const State& s) {
  for (int n = 0; n < s.n_nodes(); ++n) {
    const auto i = static_cast<size_t>(n);
    if (!s.x[i].allFinite() || !s.v[i].allFinite() || !s.a[i].allFinite())
      return Instability{
          s.t, fmt::format("non-finite position, velocity or acceleration at node {}", n), -1, n};
  }
  return std::nullopt;
}

std::optional<Instability> check_energy(double relative_error, double tolerance, double t) {
  if (relative_error <= tolerance) return std::nullopt;
  return Instability{t,
                     fmt::format("energy balance error {:.3g} % exceeds {:.3g} %",
                                 100.0 * relative_error, 100.0 * tolerance),
                     -1, -1};
}

std::optional<Instability> check_contact_energy(std::string_view model, double injected,
                                                double scale, double tolerance, double t) {
  if (injected <= tolerance * scale) return std::nullopt;  // a NaN fails this test too
  return Instability{t,
                     fmt::format("contact ({}) put {:.4g} J into the bodies, {:.3g} % of the "
                                 "energy scale {:.4g} J (its contacts can only dissipate)",
                                 model, injected, 100.0 * injected / scale, scale),
                     -1, -1};
}

std::optional<Instability> check_time_step(double dt, double dt_initial, double ratio, double t) {
  if (std::isfinite(dt) && dt >= ratio * dt_initial) return std::nullopt;
  // No stepped element (rigid bodies alone): no stable step, nothing to collapse.
  if (std::isinf(dt) && dt > 0.0 && std::isinf(dt_initial)) return std::nullopt;
  return Instability{
      t, fmt::format("stable time step collapsed to {:.3g} s (initial {:.3g} s)", dt, dt_initial),
      -1, -1};
}

}  // namespace ccm
