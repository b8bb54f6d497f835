// `ccm study run GRID --db FILE [--jobs N]`: every run of the grid not yet in the store, spread
// over local worker processes (--jobs) or MPI ranks, then the metrics of every point, the
// surface fits and the recommendation table. A killed study resumes: runs already completed
// or unstable are skipped, an interrupted one is redone.
#include <fmt/format.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "db/store/provenance.hpp"
#include "db/store/study_store.hpp"
#include "study/cli/run_command.hpp"
#include "study/cli/run_schedule.hpp"
#include "study/cli/study_commands.hpp"
#include "study/cli/study_progress.hpp"
#include "study/cli/study_tables.hpp"
#include "study/fit/study_fits.hpp"
#include "study/grid/grid_expand.hpp"
#include "study/grid/grid_file.hpp"
#include "study/metrics/point_metrics.hpp"
#include "study/metrics/thesis_trends.hpp"
#include "study/parallel/rank_context.hpp"
#include "study/runner/content_hash.hpp"
#include "study/runner/point_runner.hpp"
#include "study/scene/scene.hpp"

namespace ccm {
namespace {

namespace fs = std::filesystem;
using study::GridPoint;
using study::GridSpec;
using study::ImpactModel;

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Binds the store to the study, keeps the grid file's text (every answer states its modelling
// choices from it) and registers every point (rank 0, before any worker starts).
void prepare_store(const fs::path& db, const GridSpec& spec, const std::string& grid_hash,
                   const std::vector<PlannedRun>& runs) {
  db::StudyStore store(db);
  store.open_study(spec.title, grid_hash);
  auto transaction = store.begin();
  store.save_grid({spec.source.string(), read_text(spec.source)});
  for (const PlannedRun& r : runs) store.add_grid_point(r.point);
  transaction.commit();
}

// Runs the runs `next_run` hands out (an index into `runs`; >= runs.size() when there are no
// more) that are not done yet; each run is committed on its own. Returns the number of failed
// runs.
long run_share(const fs::path& db, const GridSpec& spec, const std::string& grid_hash,
               const std::vector<PlannedRun>& runs, const std::function<std::size_t()>& next_run,
               const db::RunProvenance& provenance) {
  db::StudyStore store(db);
  store.open_study(spec.title, grid_hash);
  long failed = 0;
  for (std::size_t i = next_run(); i < runs.size(); i = next_run()) {
    const PlannedRun& r = runs[i];
    if (!store.mark_running(r.point, r.model, provenance, db::utc_now())) continue;  // done
    try {
      store.record_run(study::run_point(spec, r.point, r.model), provenance);
    } catch (const db::StoreError&) {
      throw;  // the store itself is broken: stop this worker
    } catch (const std::exception& e) {
      store.record_failure(r.point, r.model, e.what(), provenance);
      ++failed;
    }
  }
  return failed;
}

// Forks `jobs` worker processes (each dies with its parent) and waits for all of them.
// Returns the largest exit code.
int run_forked_workers(int jobs, const std::function<int(int)>& work,
                       const std::function<void()>& while_waiting) {
  std::fflush(nullptr);
  std::vector<pid_t> children;
  for (int j = 0; j < jobs; ++j) {
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("cannot start a worker process (fork failed)");
    if (pid == 0) {
      prctl(PR_SET_PDEATHSIG, SIGKILL);  // a killed study leaves no orphan workers
      int code = exit_code::internal_error;
      try {
        code = work(j);
      } catch (const std::exception& e) {
        fmt::print(stderr, "ccm: error: worker {}: {}\n", j, e.what());
      }
      std::fflush(nullptr);
      _exit(code);
    }
    children.push_back(pid);
  }
  while_waiting();
  int worst = 0;
  for (pid_t pid : children) {
    int status = 0;
    waitpid(pid, &status, 0);
    worst = std::max(worst, WIFEXITED(status) ? WEXITSTATUS(status) : exit_code::internal_error);
  }
  return worst;
}

// The metrics of every point whose two runs are stored, the fits over the main grid's points,
// all saved in one transaction; returns them for printing.
struct DerivedResults {
  std::vector<study::PointMetrics> grid;         // the main grid's points
  std::vector<study::PointMetrics> convergence;  // the convergence points
  study::StudyFits fits;
  std::vector<study::ConvergenceRow> convergence_rows;  // each run against the finest CCM run
  std::vector<study::TrendRow> trends;  // the main grid's points whose two runs completed
};

std::vector<study::PointMetrics> point_metrics(const db::StudyStore& store,
                                               const std::vector<GridPoint>& points,
                                               std::vector<study::TrendRow>* trends = nullptr) {
  std::vector<study::PointMetrics> out;
  for (const GridPoint& p : points) {
    const auto ccm_run = store.load_run(p, ImpactModel::ccm);
    const auto rigid_run = store.load_run(p, ImpactModel::rigid);
    if (!ccm_run || !rigid_run) continue;
    out.push_back(study::compute_point_metrics(*ccm_run, *rigid_run));
    if (trends && ccm_run->completed() && rigid_run->completed()) try {
        trends->push_back(study::thesis_trend(*ccm_run, *rigid_run));
      } catch (const std::invalid_argument&) {
        // no trend row for a point whose rigid artifact never moved (nothing to normalise by)
      }
  }
  return out;
}

DerivedResults derive_results(const fs::path& db, const GridSpec& spec,
                              const std::string& grid_hash) {
  db::StudyStore store(db);
  store.open_study(spec.title, grid_hash);
  DerivedResults results;
  results.grid = point_metrics(store, study::expand_grid(spec), &results.trends);
  results.convergence = point_metrics(store, study::expand_convergence(spec));
  results.fits = study::fit_study(results.grid);
  std::vector<study::RunRecord> convergence_runs;
  for (const GridPoint& p : study::expand_convergence(spec))
    for (ImpactModel m : {ImpactModel::ccm, ImpactModel::rigid})
      if (auto run = store.load_run(p, m)) convergence_runs.push_back(std::move(*run));
  results.convergence_rows = study::compare_convergence_runs(convergence_runs);
  auto transaction = store.begin();
  for (const auto* set : {&results.grid, &results.convergence})
    for (const study::PointMetrics& m : *set) store.save_metrics(m);
  store.save_fits(results.fits);
  transaction.commit();
  return results;
}

long count_failed(const fs::path& db, const GridSpec& spec, const std::string& grid_hash) {
  db::StudyStore store(db);
  store.open_study(spec.title, grid_hash);
  long failed = 0;
  for (const db::PointStatus& s : store.status())
    for (const auto& run : {s.ccm, s.rigid}) failed += run == db::RunStatus::failed ? 1 : 0;
  return failed;
}

// Runs this process's share (run_schedule.hpp): forked workers (--jobs) take the runs longest
// first from a shared counter; an MPI rank takes every size()-th run of that order. Rank 0 shows
// progress.
int run_all(const StudyRunArgs& args, const study::RankContext& ranks, const GridSpec& spec,
            const std::string& grid_hash, const std::vector<PlannedRun>& runs) {
  const int jobs = ranks.size() > 1 ? 1 : args.jobs;
  const auto provenance = db::current_provenance(grid_hash, ranks.size(), jobs);
  const std::vector<std::size_t> order = longest_first(runs);
  SharedCounter shared;                                        // forked workers
  std::size_t dealt = static_cast<std::size_t>(ranks.rank());  // MPI ranks
  const std::function<std::size_t()> next_run = [&]() -> std::size_t {
    std::size_t k = 0;
    if (ranks.size() > 1) {
      k = dealt;
      dealt += static_cast<std::size_t>(ranks.size());
    } else {
      k = shared.next();
    }
    return k < order.size() ? order[k] : runs.size();
  };
  auto work = [&](int /*worker*/) {
    return run_share(args.db, spec, grid_hash, runs, next_run, provenance) > 0
               ? exit_code::internal_error
               : exit_code::completed;
  };
  std::unique_ptr<StudyProgress> progress;
  auto show_progress = [&] {
    if (ranks.is_root() && !args.quiet)
      progress = std::make_unique<StudyProgress>(args.db, static_cast<long>(runs.size()));
  };
  if (jobs > 1) return run_forked_workers(jobs, work, show_progress);
  show_progress();
  return work(0);
}

int study_run(const StudyRunArgs& args, const study::RankContext& ranks) {
  const GridSpec spec = study::parse_grid_file(args.grid);  // every rank: same result
  const std::string grid_hash = study::fnv1a64(read_text(args.grid));
  const std::vector<PlannedRun> runs = plan_runs(spec);

  std::string setup_error;
  if (ranks.is_root()) try {
      prepare_store(args.db, spec, grid_hash, runs);
    } catch (const db::StoreError& e) {
      setup_error = e.what();
    }
  if (ranks.broadcast_flag(!setup_error.empty())) {
    if (ranks.is_root()) fmt::print(stderr, "ccm: error: {}\n", setup_error);
    return exit_code::bad_input;
  }
  if (ranks.is_root() && !args.quiet)
    fmt::print("study \"{}\": {} runs ({} points x 2 models) on {} worker(s), store {}\n",
               spec.title, runs.size(), runs.size() / 2, ranks.size() * args.jobs,
               args.db.string());

  run_all(args, ranks, spec, grid_hash, runs);
  ranks.barrier();
  if (!ranks.is_root()) return exit_code::completed;

  const DerivedResults results = derive_results(args.db, spec, grid_hash);
  if (!args.quiet) {
    print_point_table(stdout, results.grid, results.fits);
    print_convergence_table(stdout, results.convergence_rows);
    print_trend_table(stdout, results.trends, results.grid);
  }
  if (const long failed = count_failed(args.db, spec, grid_hash); failed > 0) {
    fmt::print(stderr, "ccm: error: {} run(s) failed; `ccm study status --db {}` names them\n",
               failed, args.db.string());
    return exit_code::internal_error;
  }
  return exit_code::completed;
}

}  // namespace

int study_run_command(const StudyRunArgs& args) {
  try {
    study::RankContext ranks;
    if (args.jobs < 1) {
      fmt::print(stderr, "ccm: error: --jobs must be at least 1 (got {})\n", args.jobs);
      return exit_code::bad_input;
    }
    return study_run(args, ranks);
  } catch (const SceneError& e) {
    fmt::print(stderr, "ccm: error: {}\n", e.what());
    return exit_code::bad_input;
  } catch (const std::exception& e) {
    fmt::print(stderr, "ccm: error: {}\n", e.what());
    return exit_code::internal_error;
  }
}

}  // namespace ccm
