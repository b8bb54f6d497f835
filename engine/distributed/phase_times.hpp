// Wall time of a partitioned run by phase (docs/parallel.md): communication (halo exchanges,
// reductions, the contact surface's gathers) and the replicated contact solve; the structure
// (element forces and updates) is the rest of the step loop.
#pragma once

#include <chrono>

namespace ccm::distributed {

struct PhaseTimes {
  double communication = 0.0;  // [s]
  double contact = 0.0;        // [s]
  long messages = 0;           // point-to-point messages sent by this rank
  long message_doubles = 0;    // doubles in them
  long collectives = 0;        // reductions and gathers joined
};

// Adds the wall time of its lifetime to a counter.
class ScopedTimer {
 public:
  explicit ScopedTimer(double& total) : total_(total), start_(std::chrono::steady_clock::now()) {}
  ~ScopedTimer() {
    total_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  ScopedTimer(const ScopedTimer&) = delete;
  ScopedTimer& operator=(const ScopedTimer&) = delete;

 private:
  double& total_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace ccm::distributed
