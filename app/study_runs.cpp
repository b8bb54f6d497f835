#include "app/study_runs.hpp"

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
#include "app/study_progress.hpp"
#include "app/study_runs.hpp"
#include "app/study_tables.hpp"
#include "config/text_file.hpp"
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

// The time of a run's last sample [s].
double end_of(const study::RunRecord& r) {
  return r.artifact.time.empty() ? 0.0 : r.artifact.time.back();
}

// A point's two runs of a whole-impact study (docs/grid-file.md, "Whole impacts"), run together
// so that both end at the same time, after both have separated: the rigid run first (the cheap
// one), then the CCM run not before the rigid run's end, then the rigid run again to the CCM
// run's end when that is later (up to its first end the same run, bit for bit). Each record is
// stored as soon as it is made; a resumed pair reuses what is stored and redoes only what is
// missing or ends apart. Returns false when another process holds the pair.
bool run_pair(db::StudyStore& store, const GridSpec& spec, const GridPoint& point,
              const db::RunProvenance& provenance) {
  auto stored = [&](ImpactModel m) {
    return store.is_done(point, m) ? store.load_run(point, m) : std::nullopt;
  };
  std::optional<study::RunRecord> ccm_run = stored(ImpactModel::ccm);
  std::optional<study::RunRecord> rigid_run = stored(ImpactModel::rigid);
  if (ccm_run && rigid_run &&
      (end_of(*rigid_run) == end_of(*ccm_run) || !ccm_run->completed() || !rigid_run->completed()))
    return true;
  const ImpactModel missing = ccm_run ? ImpactModel::rigid : ImpactModel::ccm;
  if ((!ccm_run || !rigid_run) && !store.mark_running(point, missing, provenance, db::utc_now()))
    return false;  // both stored, ending apart: the rigid run is redone below without a claim
  if (!rigid_run) {
    rigid_run = study::run_point(spec, point, ImpactModel::rigid);
    store.record_run(*rigid_run, provenance);
  }
  if (!ccm_run) {
    study::PointRunOptions after;
    if (rigid_run->completed()) after.end.earliest = end_of(*rigid_run);
    ccm_run = study::run_point(spec, point, ImpactModel::ccm, after);
    store.record_run(*ccm_run, provenance);
  }
  if (ccm_run->completed() && rigid_run->completed() && end_of(*ccm_run) > end_of(*rigid_run)) {
    study::PointRunOptions longer;
    longer.end.fixed = end_of(*ccm_run);
    store.record_run(study::run_point(spec, point, ImpactModel::rigid, longer), provenance);
  }
  return true;
}

// Runs the groups of runs that share a scene (run_schedule.hpp) that `next_group` hands out (an
// index into `groups`; >= groups.size() when there are no more), each simulated once and stored
// for every member not done yet; each record is committed on its own. Returns the number of
// failed runs.
long run_share(const fs::path& db, const GridSpec& spec, const std::string& grid_hash,
               const std::vector<PlannedRun>& runs,
               const std::vector<std::vector<std::size_t>>& groups,
               const std::function<std::size_t()>& next_group, const db::RunProvenance& provenance,
               bool whole_impacts) {
  db::StudyStore store(db);
  store.open_study(spec.title, grid_hash);
  long failed = 0;
  for (std::size_t g = next_group(); g < groups.size(); g = next_group()) {
    const std::vector<std::size_t>& group = groups[g];
    const bool all_done = std::all_of(group.begin(), group.end(), [&](std::size_t i) {
      return store.is_done(runs[i].point, runs[i].model);
    });
    if (all_done && !whole_impacts) continue;
    try {
      if (whole_impacts)
        run_pair(store, spec, runs[group.front()].point, provenance);
      else if (const auto record = group_record(store, spec, runs, group, provenance))
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

long stored_point_count(const fs::path& db, const GridSpec& spec, const std::string& grid_hash) {
  db::StudyStore store(db);
  store.open_study(spec.title, grid_hash);
  return static_cast<long>(store.status().size());
}

struct StoredPoints {
  std::vector<GridPoint> grid, convergence;
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

}  // namespace

void prepare_store(const fs::path& db, const GridSpec& spec, const std::string& grid_hash,
                   const std::vector<PlannedRun>& runs) {
  db::StudyStore store(db);
  store.open_study(spec.title, grid_hash);
  auto transaction = store.begin();
  store.save_grid({spec.source.string(), read_config_text(spec.source)});
  for (const PlannedRun& r : runs) store.add_grid_point(r.point);
  transaction.commit();
}

void register_points(const fs::path& db, const GridSpec& spec, const std::string& grid_hash,
                     const std::vector<PlannedRun>& runs) {
  db::StudyStore store(db);
  store.open_study(spec.title, grid_hash);
  auto transaction = store.begin();
  for (const PlannedRun& r : runs) store.add_grid_point(r.point);
  transaction.commit();
}

DerivedResults derive_results(const fs::path& db, const GridSpec& spec,
                              const std::string& grid_hash) {
  db::StudyStore store(db);
  store.open_study(spec.title, grid_hash);
  StoredPoints points;
  for (const db::PointStatus& s : store.status())
    (study::is_convergence_point(s.point) ? points.convergence : points.grid).push_back(s.point);
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

bool whole_impact_study(const GridSpec& spec, const std::vector<PlannedRun>& runs) {
  return !runs.empty() && study::study_scene(spec, runs.front().point, ImpactModel::ccm)
                              .time.end_after_separation.has_value();
}

std::vector<GridPoint> points_at_guard(const GridSpec& spec,
                                       const std::vector<study::PointMetrics>& metrics) {
  std::vector<GridPoint> out;
  for (const study::PointMetrics& m : metrics) {
    if (!m.usable) continue;
    const Scene scene = study::study_scene(spec, m.point, ImpactModel::ccm);
    if (scene.time.end_after_separation && m.t_final >= scene.time.end * (1.0 - 1e-9))
      out.push_back(m.point);
  }
  return out;
}

int run_all(const StudyRunsSetup& args, const study::RankContext& ranks, const GridSpec& spec,
            const std::string& grid_hash, const std::vector<PlannedRun>& runs) {
  const int jobs = ranks.size() > 1 ? 1 : args.jobs;
  const auto provenance = db::current_provenance(grid_hash, ranks.size(), jobs);
  const bool whole_impacts = whole_impact_study(spec, runs);
  const std::vector<std::vector<std::size_t>> groups =
      whole_impacts ? group_by_point(runs) : group_by_scene(runs);
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
    return run_share(args.db, spec, grid_hash, runs, groups, next_run, provenance, whole_impacts) >
                   0
               ? exit_code::internal_error
               : exit_code::completed;
  };
  std::unique_ptr<StudyProgress> progress;
  auto show_progress = [&] {  // out of every run of the study (a refined one's too)
    if (ranks.is_root() && !args.quiet)
      progress = std::make_unique<StudyProgress>(args.db,
                                                 2 * stored_point_count(args.db, spec, grid_hash));
  };
  if (jobs > 1) return run_forked_workers(jobs, work, show_progress);
  show_progress();
  return work(0);
}

}  // namespace ccm
