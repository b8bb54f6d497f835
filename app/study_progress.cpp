#include "app/study_progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>

#include "app/run_schedule.hpp"
#include "db/store/study_store.hpp"

namespace ccm {
namespace {

struct RunCounts {
  long finished = 0;  // completed, unstable or failed
  long running = 0;
  double cost_finished = 0.0;  // expected cost (run_schedule.hpp) of the finished runs
  double cost_total = 0.0;     // of every run of the study
};

RunCounts count_runs(const std::filesystem::path& db) {
  db::StudyStore store(db);
  RunCounts counts;
  if (!store.open_existing_study()) return counts;
  for (const db::PointStatus& s : store.status())
    for (const study::ImpactModel model : {study::ImpactModel::ccm, study::ImpactModel::rigid}) {
      const auto& run = model == study::ImpactModel::ccm ? s.ccm : s.rigid;
      const double cost = expected_run_cost(s.point, model);
      counts.cost_total += cost;
      if (!run) continue;
      if (*run == db::RunStatus::running) {
        ++counts.running;
      } else {
        ++counts.finished;
        counts.cost_finished += cost;
      }
    }
  return counts;
}

std::string clock_text(double seconds) {
  const long s = static_cast<long>(seconds + 0.5);
  return s >= 3600 ? fmt::format("{}h{:02}m", s / 3600, (s / 60) % 60)
                   : fmt::format("{}m{:02}s", s / 60, s % 60);
}

}  // namespace

StudyProgress::StudyProgress(std::filesystem::path db, long total_runs)
    : db_(std::move(db)),
      total_(total_runs),
      terminal_(isatty(fileno(stderr)) != 0),
      start_(std::chrono::steady_clock::now()) {
  thread_ = std::thread([this] { loop(); });
}

StudyProgress::~StudyProgress() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void StudyProgress::loop() {
  std::unique_lock lock(mutex_);
  while (true) {
    lock.unlock();
    show(false);
    lock.lock();
    if (wake_.wait_for(lock, std::chrono::seconds(1), [this] { return stop_; })) break;
  }
  lock.unlock();
  show(true);
}

// ETA from the runs finished since this invocation started (resumed runs do not count).
void StudyProgress::show(bool final) {
  RunCounts counts;
  try {
    counts = count_runs(db_);
  } catch (const std::exception&) {
    return;  // the store is busy or being created: try again next second
  }
  if (finished_at_start_ < 0) {
    finished_at_start_ = counts.finished;
    cost_at_start_ = counts.cost_finished;
  }
  if (!final && !terminal_ && counts.finished == last_shown_) return;
  last_shown_ = counts.finished;
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  // The runs differ in cost by orders of magnitude and are taken longest first: the ETA
  // scales the elapsed time by the expected cost still to run over the cost run so far.
  const double cost_now = counts.cost_finished - cost_at_start_;
  std::string eta = "--";
  if (counts.finished > finished_at_start_ && cost_now > 0.0)
    eta = clock_text(elapsed / cost_now * (counts.cost_total - counts.cost_finished));
  const std::string line = fmt::format(
      "study: {}/{} runs finished ({:.0f} %), {} running, elapsed {}, ETA {}", counts.finished,
      total_,
      100.0 * static_cast<double>(counts.finished) / static_cast<double>(std::max(total_, 1L)),
      counts.running, clock_text(elapsed), final ? "0m00s" : eta);
  if (terminal_)
    fmt::print(stderr, "\r{:<100}{}", line, final ? "\n" : "");
  else
    fmt::print(stderr, "{}\n", line);
  std::fflush(stderr);
}

}  // namespace ccm
