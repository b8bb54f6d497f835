// Running a study's planned runs into its store and deriving its results: what `ccm study run`
// and `ccm study refine` share. A killed study resumes: runs already completed or unstable are
// skipped, an interrupted one is redone; each group of runs that share a scene is simulated once.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "app/run_schedule.hpp"
#include "records/point_metrics.hpp"
#include "run/parallel/rank_context.hpp"
#include "study/fit/study_fits.hpp"
#include "study/grid/grid_spec.hpp"
#include "study/metrics/convergence.hpp"
#include "study/metrics/thesis_trends.hpp"

namespace ccm {

struct StudyRunsSetup {
  std::filesystem::path db;
  int jobs = 1;        // local worker processes (without MPI)
  bool quiet = false;  // no progress line
};

// Binds the store to the study, keeps the grid file's text (every answer states its modelling
// choices from it) and registers every point (rank 0, before any worker starts).
void prepare_store(const std::filesystem::path& db, const study::GridSpec& spec,
                   const std::string& grid_hash, const std::vector<PlannedRun>& runs);

// Registers the runs' points in the study the store holds (rank 0, before any worker starts).
void register_points(const std::filesystem::path& db, const study::GridSpec& spec,
                     const std::string& grid_hash, const std::vector<PlannedRun>& runs);

// Whether the study compares whole impacts (its scenes end after separation): then a point's two
// runs are run together and no run is shared between points (docs/grid-file.md).
bool whole_impact_study(const study::GridSpec& spec, const std::vector<PlannedRun>& runs);

// The points of a whole-impact study whose runs reached the guard ([time] end) before both bodies
// had separated: their final state is not read after the impact.
std::vector<study::GridPoint> points_at_guard(const study::GridSpec& spec,
                                              const std::vector<study::PointMetrics>& metrics);

// Runs this process's share (run_schedule.hpp): forked workers (--jobs) take the runs longest
// first from a shared counter; an MPI rank takes every size()-th run of that order. Rank 0 shows
// progress. Returns the largest exit code of the workers.
int run_all(const StudyRunsSetup& setup, const study::RankContext& ranks,
            const study::GridSpec& spec, const std::string& grid_hash,
            const std::vector<PlannedRun>& runs);

// The metrics of every point of the study whose two runs are stored (the grid's, the
// convergence runs', and those `study refine` added), the fits over all but the convergence
// points, all saved in one transaction; returned for printing.
struct DerivedResults {
  std::vector<study::PointMetrics> grid;         // every point but the convergence points
  std::vector<study::PointMetrics> convergence;  // the convergence points
  study::StudyFits fits;
  std::vector<study::ConvergenceRow> convergence_rows;  // each run against the finest CCM run
  std::vector<study::TrendRow> trends;  // the grid's points whose two runs completed
};
DerivedResults derive_results(const std::filesystem::path& db, const study::GridSpec& spec,
                              const std::string& grid_hash);

// The runs of the study that failed (an exception, not an unstable run).
long count_failed(const std::filesystem::path& db, const study::GridSpec& spec,
                  const std::string& grid_hash);

}  // namespace ccm
