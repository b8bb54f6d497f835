#include "study/cli/run_schedule.hpp"

#include <sys/mman.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <new>
#include <stdexcept>

#include "study/grid/grid_expand.hpp"
#include "study/metrics/convergence.hpp"

namespace ccm {

std::vector<PlannedRun> plan_runs(const study::GridSpec& spec) {
  std::vector<PlannedRun> runs;
  for (const auto& points : {study::expand_grid(spec), study::expand_convergence(spec)})
    for (const study::GridPoint& p : points)
      for (study::ImpactModel m : {study::ImpactModel::ccm, study::ImpactModel::rigid})
        runs.push_back({p, m});
  return runs;
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

}  // namespace ccm
