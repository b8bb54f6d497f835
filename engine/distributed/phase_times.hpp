// Wall time of a partitioned run by phase (docs/parallel.md): communication (halo exchanges,
// reductions, the contact surface's gathers) and the replicated contact solve; the structure
// (element forces and updates) is the rest of the step loop.
#pragma once

#include <time.h>

#include <chrono>

namespace ccm::distributed {

// On a machine shared with other work, wall time mixes the algorithm with the scheduler (a rank
// waits for a peer that is not running); thread CPU time is kept beside it.
struct Seconds {
  double wall = 0.0;
  double cpu = 0.0;  // CLOCK_THREAD_CPUTIME_ID
};

struct PhaseTimes {
  Seconds communication;  // includes the waiting for the peers' messages
  // Of the communication: the halo exchanges, and the contact's gathers and joins (the rest are
  // the reductions of the step, the energies and the samples).
  Seconds halo, contact_communication;
  Seconds contact;
  long messages = 0;         // point-to-point messages sent by this rank
  long message_doubles = 0;  // doubles in them
  long collectives = 0;      // reductions and gathers joined
  long region_gathers = 0;   // of them, gathers of the contact region
};

inline double thread_cpu_now() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// Adds the wall and thread CPU time of its lifetime to a counter.
class ScopedTimer {
 public:
  explicit ScopedTimer(Seconds& total)
      : total_(total), start_(std::chrono::steady_clock::now()), cpu_start_(thread_cpu_now()) {}
  ~ScopedTimer() {
    total_.wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    total_.cpu += thread_cpu_now() - cpu_start_;
  }
  ScopedTimer(const ScopedTimer&) = delete;
  ScopedTimer& operator=(const ScopedTimer&) = delete;

 private:
  Seconds& total_;
  std::chrono::steady_clock::time_point start_;
  double cpu_start_;
};

}  // namespace ccm::distributed
