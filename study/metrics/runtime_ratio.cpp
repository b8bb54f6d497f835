#include "study/metrics/runtime_ratio.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace ccm::study {

namespace {
void require_positive(double value, const char* name) {
  if (!(value > 0.0) || !std::isfinite(value))
    throw std::invalid_argument(std::string(name) + " must be positive and finite, got " +
                                std::to_string(value));
}
}  // namespace

double normalised_runtime(double average_iteration_seconds, double initial_stable_dt) {
  require_positive(average_iteration_seconds, "AIR (average iteration runtime)");
  require_positive(initial_stable_dt, "ISTS (initial stable time step)");
  return average_iteration_seconds / initial_stable_dt;  // eq. 2.41 / 2.42
}

double total_runtime(double t_final, double normalised_runtime) {
  return t_final * normalised_runtime;  // eq. 2.43
}

double runtime_ratio(double nt_ccm, double nt_rigid) {
  require_positive(nt_rigid, "NT_rigid");
  return nt_ccm / nt_rigid;  // eq. 2.40
}

}  // namespace ccm::study
