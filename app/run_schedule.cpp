#include "app/run_schedule.hpp"

#include <sys/mman.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <new>
#include <stdexcept>

#include "records/content_hash.hpp"
#include "run/runner/study_scene.hpp"
#include "study/metrics/convergence.hpp"

namespace ccm {

std::vector<PlannedRun> plan_runs(const study::GridSpec& spec, const study::StudyPoints& points) {
  std::vector<PlannedRun> runs;
  for (const auto* set : {&points.grid, &points.convergence})
    for (const study::GridPoint& p : *set)
      for (study::ImpactModel m : {study::ImpactModel::ccm, study::ImpactModel::rigid})
        runs.push_back({p, m, study::fnv1a64(study::study_run_identity(spec, p, m))});
  return runs;
}

std::vector<std::vector<std::size_t>> group_by_scene(const std::vector<PlannedRun>& runs) {
  std::vector<std::vector<std::size_t>> groups;
  std::map<std::pair<study::ImpactModel, std::string>, std::size_t> group_of;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const auto key = std::make_pair(runs[i].model, runs[i].scene_hash);
    const auto [it, is_new] = group_of.emplace(key, groups.size());
    if (is_new) groups.emplace_back();
    groups[it->second].push_back(i);
  }
  return groups;
}

std::vector<std::vector<std::size_t>> group_by_point(const std::vector<PlannedRun>& runs) {
  std::vector<std::vector<std::size_t>> groups;
  std::map<int, std::size_t> group_of;  // by point index
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const auto [it, is_new] = group_of.emplace(runs[i].point.index, groups.size());
    if (is_new) groups.emplace_back();
    groups[it->second].push_back(i);
  }
  for (auto& g : groups)  // the CCM run first: it sets the group's expected cost
    std::stable_sort(g.begin(), g.end(), [&](std::size_t a, std::size_t b) {
      return runs[a].model == study::ImpactModel::ccm && runs[b].model != study::ImpactModel::ccm;
    });
  return groups;
}

double expected_run_cost(const study::GridPoint& point, study::ImpactModel model) {
  constexpr double kRigidCost = 60.0;
  const double per_scale = 1.0 / std::pow(study::mesh_scale(point), 4);
  if (model == study::ImpactModel::rigid) return kRigidCost * per_scale;
  return std::sqrt(point.modulus_ratio) * per_scale;
}

std::vector<std::size_t> longest_first(const std::vector<PlannedRun>& runs) {
  std::vector<double> cost(runs.size());
  std::vector<std::size_t> order(runs.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    order[i] = i;
    cost[i] = expected_run_cost(runs[i].point, runs[i].model);
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });
  return order;
}

std::vector<std::size_t> longest_first(const std::vector<PlannedRun>& runs,
                                       const std::vector<std::vector<std::size_t>>& groups) {
  std::vector<PlannedRun> first;
  for (const auto& g : groups) first.push_back(runs[g.front()]);
  return longest_first(first);
}

using Counter = std::atomic<std::size_t>;
static_assert(Counter::is_always_lock_free, "a process-shared counter must be lock-free");

SharedCounter::SharedCounter() {
  memory_ =
      mmap(nullptr, sizeof(Counter), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
  if (memory_ == MAP_FAILED) throw std::runtime_error("cannot map the workers' shared counter");
  new (memory_) Counter(0);
}

SharedCounter::~SharedCounter() { munmap(memory_, sizeof(Counter)); }

std::size_t SharedCounter::next() { return static_cast<Counter*>(memory_)->fetch_add(1); }

int threads_per_job(int cores, int jobs) { return std::max(1, cores / std::max(1, jobs)); }

}  // namespace ccm
