#include "run/parallel/rank_context.hpp"

#include <mpi.h>

#include <chrono>
#include <cstdlib>
#include <initializer_list>
#include <thread>

namespace ccm::study {

bool launched_by_mpi() {
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "MPI_LOCALNRANKS"})
    if (std::getenv(var) != nullptr) return true;
  return false;
}

RankContext::RankContext() {
  if (!launched_by_mpi()) return;
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (!initialised) MPI_Init(nullptr, nullptr);
  mpi_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

RankContext::~RankContext() {
  if (!mpi_) return;
  int finalised = 0;
  MPI_Finalized(&finalised);
  if (!finalised) MPI_Finalize();
}

void RankContext::barrier() const {
  if (mpi_) MPI_Barrier(MPI_COMM_WORLD);
}

void RankContext::barrier_asleep() const {
  if (!mpi_) return;
  MPI_Request request;
  MPI_Ibarrier(MPI_COMM_WORLD, &request);
  for (int done = 0;;) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

long RankContext::sum(long value) const {
  if (!mpi_) return value;
  long total = 0;
  MPI_Allreduce(&value, &total, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
  return total;
}

bool RankContext::broadcast_flag(bool flag) const {
  if (!mpi_) return flag;
  int value = flag ? 1 : 0;
  MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return value != 0;
}

std::string RankContext::broadcast_text(std::string text) const {
  if (!mpi_) return text;
  unsigned long long length = text.size();
  MPI_Bcast(&length, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
  text.resize(static_cast<std::size_t>(length));
  MPI_Bcast(text.data(), static_cast<int>(length), MPI_CHAR, 0, MPI_COMM_WORLD);
  return text;
}

void RankContext::abort_all(int code) const {
  if (mpi_) MPI_Abort(MPI_COMM_WORLD, code);
}

}  // namespace ccm::study
