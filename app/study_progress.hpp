// The progress line of `ccm study run`: a thread that reads the store once a second and shows
// runs finished out of the total, runs in progress, elapsed time and an ETA (weighted by the
// runs' expected costs, app/run_schedule.hpp). It reads the
// store rather than listening to workers, so it counts every worker process and MPI rank alike.
#pragma once

#include <atomic>
#include <condition_variable>
#include <filesystem>
#include <mutex>
#include <thread>

namespace ccm {

class StudyProgress {
 public:
  StudyProgress(std::filesystem::path db, long total_runs);
  ~StudyProgress();  // stops the thread and prints the final line
  StudyProgress(const StudyProgress&) = delete;
  StudyProgress& operator=(const StudyProgress&) = delete;

 private:
  void loop();
  void show(bool final);

  std::filesystem::path db_;
  long total_;
  long finished_at_start_ = -1;
  double cost_at_start_ = 0.0;
  long last_shown_ = -1;
  bool terminal_ = false;
  std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace ccm
