// The stability monitor: a run that goes unstable ends with a verdict, a time and a reason,
// never a crash and never non-finite numbers written as results.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "engine/core/state.hpp"
#include "engine/element/internal_force.hpp"

namespace ccm {

struct MonitorSettings {
  double energy_tolerance = 0.05;   // |energy balance error| / energy scale that ends a run
  int check_interval = 50;          // steps between energy and finiteness checks
  double dt_collapse_ratio = 1e-4;  // dt below this fraction of the initial dt ends a run
};

struct Instability {
  double time = 0.0;
  std::string reason;
  int element = -1;
  int node = -1;
};

// Energy balance (docs/equations.md "Energy balance"): KE + IE - (KE_0 + IE_0) - W_ext, relative to
// the largest energy seen in the run so that a body at rest that is then loaded is judged fairly.
class EnergyBalance {
 public:
  // floor: the smallest energy scale the error is measured against [J], so that round-off on a
  // body at rest is not read as an instability (the integrator passes 1e-12 M c_d,max^2).
  void start(double kinetic, double internal, double floor);
  // Returns the relative error after this update.
  double update(double kinetic, double internal, double external_work);
  double max_relative_error() const { return max_error_; }
  double scale() const { return scale_; }  // the largest energy seen (or the floor) [J]
  double last_relative_error() const { return last_error_; }

 private:
  double initial_ = 0.0;
  double scale_ = 0.0;
  double last_error_ = 0.0;
  double max_error_ = 0.0;
};

// Kinetic energy of the half-step velocities, 1/2 sum m v_{n-1/2} . v_{n+1/2}
// = 1/2 sum m (|v_n|^2 - (dt/2)^2 |a_n|^2): with it, KE + IE is exactly conserved by central
// difference for a linear system, so the energy balance measures drift and instability rather
// than the O((omega dt)^2) oscillation of the synchronous kinetic energy of high modes.
// Over nodes [0, n_nodes) (default: all; a subdomain counts the nodes it owns), summed in a
// fixed order (fixed_order_sum.hpp): the same bits for any thread count.
double leapfrog_kinetic_energy(const State& s, double dt, int threads = 1, int n_nodes = -1);

std::optional<Instability> check_elements(const InternalForceResult& r, double t);
std::optional<Instability> check_finite(const State& s);
std::optional<Instability> check_energy(double relative_error, double tolerance, double t);
// A contact model's injected energy (ContactModel::injected_energy) beyond tolerance x scale.
std::optional<Instability> check_contact_energy(std::string_view model, double injected,
                                                double scale, double tolerance, double t);
std::optional<Instability> check_time_step(double dt, double dt_initial, double ratio, double t);

}  // namespace ccm
