// Normalised runtime and runtime ratio of the two models (thesis eqs. 2.40-2.43).
//
// Two readings of the same equations (docs/store.md, "Cost"):
//  - measured (what the study decides with): TR = the CPU seconds the run's step loop took,
//    RTR = TR_CCM / TR_rigid;
//  - the thesis's estimate: NT = AIR / ISTS with ISTS the structural step at t = 0, TR = t_f NT.
//    It assumes every run steps at its initial step to the end, which a contact-limited run does
//    not (the rigid model steps at its penalty limit once in contact): kept beside the measured
//    ratio for comparison with the thesis, never used for a decision.
#pragma once

namespace ccm::study {

// NT = AIR / ISTS: average wall time per iteration over the initial stable time step
// (eqs. 2.41, 2.42), in wall seconds per simulated second.
double normalised_runtime(double average_iteration_seconds, double initial_stable_dt);

// TR = T_final NT: estimated total runtime [s] (eq. 2.43).
double total_runtime(double t_final, double normalised_runtime);

// RTR = NT_CCM / NT_rigid (eq. 2.40); equally TR_CCM / TR_rigid (same t_f), the form used with
// the measured TR.
double runtime_ratio(double nt_ccm, double nt_rigid);

}  // namespace ccm::study
