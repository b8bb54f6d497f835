// `ccm study run GRID --db FILE [--jobs N]`: every run of the grid not yet in the store, spread
// over local worker processes (--jobs) or MPI ranks, then the metrics of every point, the
// surface fits and the recommendation table. A killed study resumes: runs already completed
// or unstable are skipped, an interrupted one is redone.
#include <fmt/format.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "app/run_command.hpp"
#include "app/run_schedule.hpp"
#include "app/study_commands.hpp"
#include "app/study_progress.hpp"
#include "app/study_tables.hpp"
#include "db/store/provenance.hpp"
#include "db/store/study_store.hpp"
#include "engine/threads/thread_count.hpp"
#include "records/content_hash.hpp"
#include "run/parallel/rank_context.hpp"
#include "run/runner/point_runner.hpp"
#include "run/scene/scene.hpp"
#include "study/fit/study_fits.hpp"
#include "study/grid/grid_file.hpp"
#include "study/metrics/point_metrics.hpp"
#include "study/metrics/thesis_trends.hpp"

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

// The record a group of runs that share a scene stores: a member's stored result when one is
// done already (a resumed study), else the group's first run simulated now (claimed first, so
// that no other process runs it at the same time). Empty when another process claimed it.
std::optional<study::RunRecord> group_record(db::StudyStore& store, const GridSpec& spec,
                                             const std::vector<PlannedRun>& runs,
                                             const std::vector<std::size_t>& group,
                                             const db::RunProvenance& provenance) {
  for (std::size_t i : group)
    if (store.is_done(runs[i].point, runs[i].model))
      return store.load_run(runs[i].point, runs[i].model);
  const PlannedRun& first = runs[group.front()];
  if (!store.mark_running(first.point, first.model, provenance, db::utc_now()))
    return store.load_run(first.point, first.model);  // finished meanwhile by another process
  study::RunRecord run = study::run_point(spec, first.point, first.model);
  store.record_run(run, provenance);
  return run;
}

// The group's record stored for every member not done yet, each as a reuse of the simulated run.
void store_reuses(db::StudyStore& store, const study::RunRecord& source,
                  const std::vector<PlannedRun>& runs, const std::vector<std::size_t>& group,
                  const db::RunProvenance& provenance) {
  for (std::size_t i : group) {
    if (store.is_done(runs[i].point, runs[i].model)) continue;
    study::RunRecord copy = source;
    copy.point = runs[i].point;
    copy.reuses_point = source.reuses_point.value_or(source.point.index);
    store.record_run(copy, provenance);
  }
}

// Runs the groups of runs that share a scene (run_schedule.hpp) that `next_group` hands out (an
// index into `groups`; >= groups.size() when there are no more), each simulated once and stored
// for every member not done yet; each record is committed on its own. Returns the number of
// failed runs.
long run_share(const fs::path& db, const GridSpec& spec, const std::string& grid_hash,
               const std::vector<PlannedRun>& runs,
               const std::vector<std::vector<std::size_t>>& groups,
               const std::function<std::size_t()>& next_group,
               const db::RunProvenance& provenance) {
  db::StudyStore store(db);
  store.open_study(spec.title, grid_hash);
  long failed = 0;
  for (std::size_t g = next_group(); g < groups.size(); g = next_group()) {
    const std::vector<std::size_t>& group = groups[g];
    const bool all_done = std::all_of(group.begin(), group.end(), [&](std::size_t i) {
      return store.is_done(runs[i].point, runs[i].model);
    });
    if (all_done) continue;
    try {
      if (const auto record = group_record(store, spec, runs, group, provenance))
        store_reuses(store, *record, runs, group, provenance);
    } catch (const db::StoreError&) {
      throw;  // the store itself is broken: stop this worker
    } catch (const std::exception& e) {
      for (std::size_t i : group)
        if (!store.is_done(runs[i].point, runs[i].model)) {
          store.record_failure(runs[i].point, runs[i].model, e.what(), provenance);
          ++failed;
        }
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
                              const std::string& grid_hash, const study::StudyPoints& points) {
  db::StudyStore store(db);
  store.open_study(spec.title, grid_hash);
  DerivedResults results;
  results.grid = point_metrics(store, points.grid, &results.trends);
  results.convergence = point_metrics(store, points.convergence);
  results.fits = study::fit_study(results.grid);
  std::vector<study::RunRecord> convergence_runs;
  for (const GridPoint& p : points.convergence)
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
  const std::vector<std::vector<std::size_t>> groups = group_by_scene(runs);
  const std::vector<std::size_t> order = longest_first(runs, groups);
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
    return k < order.size() ? order[k] : groups.size();
  };
  auto work = [&](int /*worker*/) {
    return run_share(args.db, spec, grid_hash, runs, groups, next_run, provenance) > 0
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
  const study::StudyPoints points = study::study_points(spec);  // checks a template's scenes
  const std::vector<PlannedRun> runs = plan_runs(spec, points);

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
    fmt::print(
        "study \"{}\": {} runs ({} points x 2 models; {} distinct scenes, each simulated once) "
        "on {} worker(s), store {}\n",
        spec.title, runs.size(), runs.size() / 2, group_by_scene(runs).size(),
        ranks.size() * args.jobs, args.db.string());

  run_all(args, ranks, spec, grid_hash, runs);
  ranks.barrier();
  if (!ranks.is_root()) return exit_code::completed;

  const DerivedResults results = derive_results(args.db, spec, grid_hash, points);
  if (!args.quiet) {
    print_point_table(stdout, results.grid, results.fits);
    print_convergence_table(stdout, results.convergence_rows);
    if (!spec.scene_template) print_trend_table(stdout, results.trends, results.grid);
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
    try {  // each forked worker inherits it; MPI ranks fill the cores one per rank
      const int automatic = ranks.size() > 1 ? 1 : threads_per_job(available_cores(), args.jobs);
      set_default_threads(resolve_threads(args.threads, automatic));
    } catch (const std::invalid_argument& e) {
      fmt::print(stderr, "ccm: error: {}\n", e.what());
      return exit_code::bad_input;
    }
    return study_run(args, ranks);
  } catch (const ConfigError& e) {
    fmt::print(stderr, "ccm: error: {}\n", e.what());
    return exit_code::bad_input;
  } catch (const std::exception& e) {
    fmt::print(stderr, "ccm: error: {}\n", e.what());
    return exit_code::internal_error;
  }
}

}  // namespace ccm
