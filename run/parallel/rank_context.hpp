// Which share of a study this process runs: one process alone, or one MPI rank of
// `mpirun -np N ccm study run ...`. A study is many independent runs, so ranks split the list
// of runs round-robin and never talk during a run; rank 0 reports progress.
#pragma once

#include <cstddef>
#include <string>

namespace ccm::study {

class RankContext {
 public:
  // Initialises MPI only when the process was started by an MPI launcher (Open MPI, MPICH or
  // PMIx environment variables), so a plain `ccm` never pays for MPI start-up.
  RankContext();
  ~RankContext();
  RankContext(const RankContext&) = delete;
  RankContext& operator=(const RankContext&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool is_root() const { return rank_ == 0; }
  // Round-robin ownership of the i-th run of the study's ordered run list.
  bool owns(std::size_t run_index) const {
    return run_index % static_cast<std::size_t>(size_) == static_cast<std::size_t>(rank_);
  }
  // Waits for every rank (no-op without MPI).
  void barrier() const;
  // The same, asleep between polls (1 ms) instead of spinning: ranks that wait for a long
  // computation on another leave the cores to it.
  void barrier_asleep() const;
  // Sum of a count over all ranks (identity without MPI).
  long sum(long value) const;
  // Rank 0's flag, on every rank (identity without MPI).
  bool broadcast_flag(bool flag) const;
  // Rank 0's text, on every rank (identity without MPI).
  std::string broadcast_text(std::string text) const;
  // Ends every rank of the job with `code` (MPI_Abort), for a failure met by some ranks only,
  // which would leave the others waiting in a collective; returns without MPI.
  void abort_all(int code) const;

 private:
  bool mpi_ = false;
  int rank_ = 0;
  int size_ = 1;
};

// True when environment variables of an MPI launcher are present.
bool launched_by_mpi();

}  // namespace ccm::study
