// Which run of a study a worker does next. The runs of one grid differ in cost by four orders of
// magnitude (a CCM run at ER 1e6 takes minutes, a rigid run a fraction of a second), so a fixed
// split (run i to worker i mod N) leaves workers idle: with two workers one got every CCM run.
// Instead the runs are taken longest first (LPT scheduling) from one shared counter by whichever
// worker is free; over MPI ranks, which share no memory, the longest-first order is dealt out
// round-robin. The results do not depend on who runs what: each run is deterministic.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "records/grid_point.hpp"
#include "run/runner/study_scene.hpp"
#include "study/grid/grid_spec.hpp"

namespace ccm {

struct PlannedRun {
  study::GridPoint point;
  study::ImpactModel model;
  std::string scene_hash;  // FNV-1a 64 of the run's identity (run/runner/study_scene.hpp)
};

// Every run of the grid file's points, in a fixed order: the grid's points, then the
// convergence points, each with its CCM run before its rigid run.
std::vector<PlannedRun> plan_runs(const study::GridSpec& spec, const study::StudyPoints& points);

// The runs that share a model and a scene text, as indices into `runs` in plan order: each
// group is simulated once (by its first run) and its record stored for every member. A rigid
// run does not read ER, a CCM run does not read the penalty or its damping, and a convergence
// point at mesh scale 1 repeats its grid point: those repeat a scene. Groups are in the order
// of their first run.
std::vector<std::vector<std::size_t>> group_by_scene(const std::vector<PlannedRun>& runs);

// The two runs of each point, as indices into `runs` (its CCM run, then its rigid run), in plan
// order: a whole-impact study runs them together (study_runs.hpp) and shares no scene between
// points (a run's end depends on its partner's).
std::vector<std::vector<std::size_t>> group_by_point(const std::vector<PlannedRun>& runs);

// The expected cost of a run, in relative units: a CCM run sqrt(ER) / s^4, a rigid run 60 / s^4,
// s the mesh scale. The stiff sphere's stable step falls as 1 / c_I ~ 1 / sqrt(E_I); the element
// count grows as s^-3 and the step count as s^-1. The rigid runs' 60 is measured on the default
// grid (1.6-4.3 s at s = 1, against 42-67 s for a CCM run at ER 1e6). An estimate for ordering
// and the ETA, nothing else.
double expected_run_cost(const study::GridPoint& point, study::ImpactModel model);

// Indices into `runs`, the highest expected cost first; ties keep the plan's order, so the order
// is deterministic.
std::vector<std::size_t> longest_first(const std::vector<PlannedRun>& runs);

// Indices into `groups` (of group_by_scene), by the expected cost of each group's first run,
// the highest first; ties keep the groups' order.
std::vector<std::size_t> longest_first(const std::vector<PlannedRun>& runs,
                                       const std::vector<std::vector<std::size_t>>& groups);

// Threads per run when `jobs` workers share `cores`: max(1, cores / jobs), so that the workers'
// threads together fill the cores without oversubscribing them.
int threads_per_job(int cores, int jobs);

// A counter shared by forked worker processes (an anonymous shared mapping, created before the
// fork): next() hands out 0, 1, 2, ... once each across all of them.
class SharedCounter {
 public:
  SharedCounter();
  ~SharedCounter();
  SharedCounter(const SharedCounter&) = delete;
  SharedCounter& operator=(const SharedCounter&) = delete;
  std::size_t next();

 private:
  void* memory_ = nullptr;
};

}  // namespace ccm
