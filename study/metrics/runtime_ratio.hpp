// Normalised runtime and runtime ratio of the two models (thesis eqs. 2.40-2.43).
#pragma once

namespace ccm::study {

// NT = AIR / ISTS: average wall time per iteration over the initial stable time step
// (eqs. 2.41, 2.42), in wall seconds per simulated second.
double normalised_runtime(double average_iteration_seconds, double initial_stable_dt);

// TR = T_final NT: estimated total runtime [s] (eq. 2.43).
double total_runtime(double t_final, double normalised_runtime);

// RTR = NT_CCM / NT_rigid (eq. 2.40).
double runtime_ratio(double nt_ccm, double nt_rigid);

}  // namespace ccm::study
