#include "engine/distributed/node_gather.hpp"

#include <mpi.h>

namespace ccm::distributed {

GatherPlan make_gather_plan(const std::vector<int>& nodes, const Subdomain& d,
                            const std::vector<int>& owners, const std::vector<int>& local_of) {
  std::vector<std::vector<int>> owned_by(static_cast<size_t>(d.n_ranks));
  for (int g : nodes) owned_by[static_cast<size_t>(owners[static_cast<size_t>(g)])].push_back(g);
  GatherPlan plan;
  for (int g : owned_by[static_cast<size_t>(d.rank)])
    plan.owned_local.push_back(local_of[static_cast<size_t>(g)]);
  for (const std::vector<int>& list : owned_by) {
    plan.counts.push_back(static_cast<int>(list.size()));
    plan.displs.push_back(static_cast<int>(plan.global.size()));
    plan.global.insert(plan.global.end(), list.begin(), list.end());
  }
  return plan;
}

void allgather_nodes(const GatherPlan& plan, int width, const std::vector<double>& send,
                     std::vector<double>& receive, PhaseTimes& times) {
  receive.resize(static_cast<size_t>(width) * plan.global.size());
  std::vector<int> counts(plan.counts), displs(plan.displs);
  for (int& c : counts) c *= width;
  for (int& d : displs) d *= width;
  ScopedTimer timer(times.communication);
  ++times.collectives;
  MPI_Allgatherv(send.data(), static_cast<int>(send.size()), MPI_DOUBLE, receive.data(),
                 counts.data(), displs.data(), MPI_DOUBLE, MPI_COMM_WORLD);
}

}  // namespace ccm::distributed
