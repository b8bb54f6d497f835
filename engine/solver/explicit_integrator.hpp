// Explicit central difference (Newmark beta = 0, gamma = 1/2) in the Predict-Evaluate-Correct
// order of thesis 2.5.2 (eq. 2.27-2.31; docs/equations.md "Explicit central difference"):
//   1. predict  x_{n+1} = x_n + dt v_n + dt^2/2 a_n,   v* = v_n + dt/2 a_n
//   2. evaluate a_{n+1} = M^-1 (f_ext(t_{n+1}) + f_int(x_{n+1}))  (+ gravity; f_ext: the
//      surface loads and the state loads)
//   3. contact  the contact model corrects x_{n+1} and v*
//   4. boundary conditions (fixed nodes, then the kinematic constraints: slides, pin joints)
//   5. correct  v_{n+1} = v* + dt/2 a_{n+1}
// The step is dt = min(safety * min_e h_e / c_d,e on the current configuration, max_dt,
// contact limit), clipped so that output samples fall on exact multiples of the interval.
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "engine/bc/kinematic_constraint.hpp"
#include "engine/bc/state_load.hpp"
#include "engine/contact/contact_model.hpp"
#include "engine/core/step_safety.hpp"
#include "engine/monitor/stability_monitor.hpp"
#include "engine/observe/history.hpp"
#include "engine/solver/domain_coupling.hpp"
#include "engine/solver/model.hpp"

namespace ccm {

struct TimeControl {
  double end_time = 0.0;
  double dt_safety = kDefaultDtSafety;
  double max_dt = std::numeric_limits<double>::infinity();
  double output_interval = 0.0;  // 0: only the initial and final states
  long max_steps = 0;            // 0: no limit
  // >= 0: the run ends at the first output sample at which the contact, having touched, has been
  // open (ContactLedger::touching false) for this hold time [s]; end_time is then the guard.
  // < 0: the run ends at end_time.
  double end_after_separation = -1.0;
  // With end_after_separation: the run does not end before this time [s] (another run's end,
  // when two runs are compared on common sample times).
  double earliest_end = 0.0;
};

// Why a completed run stopped: at its end time, or once its bodies had separated for the hold.
enum class RunEnd { end_time, separated };
std::string_view to_string(RunEnd e);

enum class Verdict { completed, unstable };
std::string_view to_string(Verdict v);

// What set a step's length (each step counted once, by the bound that was smallest; a step cut
// short to land on an output time or the end time counts as `landing`).
enum class StepLimiter { structure, contact, max_dt, landing };
std::string_view to_string(StepLimiter l);

// Steps per limiter; the four counts sum to RunSummary::steps.
struct StepLimiterCounts {
  long structure = 0;  // dt_safety x the elements' stable step (docs/time-step.md)
  long contact = 0;    // the contact model's limit (docs/contact-time-step.md)
  long max_dt = 0;     // the scene's [time] max_dt
  long landing = 0;    // shortened to land on an output time or the end time
  long total() const { return structure + contact + max_dt + landing; }
  long& operator[](StepLimiter l);
};

struct RunSummary {
  Verdict verdict = Verdict::completed;
  Instability instability;  // meaningful when unstable
  RunEnd ended_by = RunEnd::end_time;
  bool touched = false;             // the contact acted at some step
  double contact_opened_at = -1.0;  // (separated) when the contact last opened [s]
  long steps = 0;
  double end_time = 0.0;  // time reached
  double dt_min = std::numeric_limits<double>::infinity();
  double dt_max = 0.0;
  double dt_initial = 0.0;  // dt_safety x the structural stable step at t = 0 (ISTS, eq. 2.42)
  double dt_first = 0.0;    // the first step actually taken (0: none)
  double dt_mean = 0.0;     // end_time / steps (0: no step)
  // The smallest step the contact model set (infinity when it never set one) and the time at
  // which the first such step started (-1 when none).
  double dt_contact_min = std::numeric_limits<double>::infinity();
  double first_contact_step_time = -1.0;
  StepLimiterCounts limiters;
  double wall_seconds = 0.0;       // whole run, initialisation included
  double step_wall_seconds = 0.0;  // the step loop alone (set-up and meshing excluded)
  // CPU time of the step loop: the calling thread's (CLOCK_THREAD_CPUTIME_ID) on one thread, the
  // process's (CLOCK_PROCESS_CPUTIME_ID, every thread of the run) on more.
  double step_cpu_seconds = 0.0;
  double ns_per_element_step = 0.0;
  double energy_balance_error = 0.0;  // largest relative error seen at the checks
  int n_nodes = 0;
  int n_elements = 0;  // the elements stepped (a rigid body's are not)
  int threads = 1;     // the threads the run used
};

struct Progress {
  double t;
  double end_time;
  long steps;
  double dt;
  double wall_seconds;
};
using ProgressFn = std::function<void(const Progress&)>;
using SampleFn = std::function<void(const State&)>;

struct RunOptions {
  TimeControl time;
  MonitorSettings monitor;
  ContactModel* contact = nullptr;                // none: no contact work at all
  std::vector<KinematicConstraint*> constraints;  // step 4, in this order, after fixed nodes
  std::vector<StateLoad*> loads;                  // state-dependent external forces
  HistoryRecorder* history = nullptr;             // none: nothing sampled
  SampleFn on_sample;                             // optional: sees the state at every output sample
  ProgressFn progress;  // called about every progress_seconds of wall time
  double progress_seconds = 0.5;
  // Threads for the structure's work (internal forces, stable step, nodal updates, energy sums);
  // 0: default_threads() (thread_count.hpp). The result is bitwise the same for any count; the
  // boundary conditions run on one thread, and so does a model of fewer than 8,192 elements
  // (RunSummary::threads says what was used). A contact model has its own thread setting (the
  // DCR's detection: DcrSettings::threads, by default default_threads() as well).
  int threads = 0;
  // A subdomain of a partitioned mesh (engine/distributed/): the model is the local one, and
  // history and on_sample are left to the coupling. None: a serial run.
  DomainCoupling* coupling = nullptr;
};

RunSummary run_explicit(const Model& model, const RunOptions& options);

}  // namespace ccm
