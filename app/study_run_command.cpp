// `ccm study run GRID --db FILE [--jobs N]`: every run of the grid not yet in the store, spread
// over local worker processes (--jobs) or MPI ranks (app/study_runs.hpp), then the metrics of
// every point, the surface fits and the recommendation table. A killed study resumes: runs
// already completed or unstable are skipped, an interrupted one is redone.
#include <fmt/format.h>

#include <fstream>
#include <sstream>
#include <vector>

#include "app/run_command.hpp"
#include "app/run_schedule.hpp"
#include "app/study_commands.hpp"
#include "app/study_runs.hpp"
#include "app/study_tables.hpp"
#include "config/text_file.hpp"
#include "db/store/study_store.hpp"
#include "engine/threads/thread_count.hpp"
#include "records/content_hash.hpp"
#include "run/parallel/rank_context.hpp"
#include "run/runner/study_scene.hpp"
#include "study/grid/grid_file.hpp"

namespace ccm {
namespace {

namespace fs = std::filesystem;
using study::GridSpec;

int study_run(const StudyRunArgs& args, const study::RankContext& ranks) {
  const GridSpec spec = study::parse_grid_file(args.grid);  // every rank: same result
  const std::string grid_hash = study::fnv1a64(read_config_text(args.grid));
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
        "study \"{}\": {} runs ({} points x 2 models; {}) on {} worker(s), store {}\n", spec.title,
        runs.size(), runs.size() / 2,
        whole_impact_study(spec, runs)
            ? "whole impacts: each point's two runs together, ending after both separate"
            : fmt::format("{} distinct scenes, each simulated once", group_by_scene(runs).size()),
        ranks.size() * args.jobs, args.db.string());

  run_all({args.db, args.jobs, args.quiet}, ranks, spec, grid_hash, runs);
  ranks.barrier();
  if (!ranks.is_root()) return exit_code::completed;

  const DerivedResults results = derive_results(args.db, spec, grid_hash);
  if (!args.quiet) {
    print_point_table(stdout, results.grid, results.fits);
    print_convergence_table(stdout, results.convergence_rows);
    if (!spec.scene_template) print_trend_table(stdout, results.trends, results.grid);
  }
  if (const auto guarded = points_at_guard(spec, results.grid); !guarded.empty()) {
    std::string which;
    for (const study::GridPoint& p : guarded)
      which += (which.empty() ? "" : ", ") + std::to_string(p.index);
    fmt::print(
        stderr,
        "ccm: warning: whole impacts: {} of {} points reached the guard [time] end before both "
        "bodies had "
        "separated (points {}): their final state is read before the impact ended; raise "
        "[time] end\n",
        guarded.size(), results.grid.size(), which);
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
  } catch (const db::StoreError& e) {  // mid-study: a full disk, a store that became unwritable
    fmt::print(stderr,
               "ccm: error: {}\nccm: the runs stored before it are kept; when the store can be "
               "written again, the same command resumes the study\n",
               e.what());
    return exit_code::bad_input;
  } catch (const std::exception& e) {
    fmt::print(stderr, "ccm: error: {}\n", e.what());
    return exit_code::internal_error;
  }
}

}  // namespace ccm