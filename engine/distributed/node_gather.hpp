// Nodes gathered from their owners onto every rank (docs/parallel.md "Contact across partitions",
// "Joints across partitions"): the plan says which of them this rank sends and where every rank's
// share lands in the joined buffer. The replicated contact and the replicated joints use it.
// This header is MPI-free.
#pragma once

#include <vector>

#include "engine/core/state.hpp"
#include "engine/distributed/phase_times.hpp"
#include "engine/distributed/subdomain.hpp"

namespace ccm::distributed {

// A set of nodes gathered from their owners onto every rank: this rank's part (local ids) and
// every rank's, in rank order (global ids), with the counts and offsets per rank in nodes.
struct GatherPlan {
  std::vector<int> owned_local;
  std::vector<int> global;
  std::vector<int> counts, displs;
};

// The plan for `nodes` (global ids): each from its owner, in ascending order within a rank's share.
GatherPlan make_gather_plan(const std::vector<int>& nodes, const Subdomain& d,
                            const std::vector<int>& owners, const std::vector<int>& local_of);

// A node's state as gathered: x, v, a and the lumped mass, kNodeStateWidth doubles.
constexpr int kNodeStateWidth = 10;
void pack_node_state(const State& s, size_t local, double* p);
// Into node `global` of a view; inv_m from the mass (0 for a rigid body's massless nodes, as the
// integrator's).
void unpack_node_state(const double* p, size_t global, State& view);

// A state in global numbering at the reference positions, at rest, without masses: a view that
// gathers fill in.
State global_view(const ModelMesh& mesh);

// Every rank's `send` (width doubles per node of plan.owned_local) joined into `receive` (width
// doubles per node of plan.global), counted as one collective of communication.
void allgather_nodes(const GatherPlan& plan, int width, const std::vector<double>& send,
                     std::vector<double>& receive, PhaseTimes& times);

}  // namespace ccm::distributed
