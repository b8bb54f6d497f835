// One rank's share of a partitioned model: its elements, the nodes they touch (its own first,
// then copies of nodes other ranks own) and, per neighbouring rank, the nodes the two share.
// Built identically on every rank from the global model and the element partition, without
// communication.
#pragma once

#include <vector>

#include "engine/solver/model.hpp"

namespace ccm::distributed {

struct Neighbour {
  int rank = 0;
  std::vector<int> nodes;  // local ids of the shared nodes, in ascending global id
};

struct Subdomain {
  int rank = 0;
  int n_ranks = 1;
  Model model;                        // the local model: local elements and nodes
  std::vector<int> global_node;       // local node -> global node
  int owned_nodes = 0;                // local nodes [0, owned_nodes) are this rank's own
  std::vector<Neighbour> neighbours;  // ascending rank
  // The ranks whose elements touch each local shared node, ascending (CSR over `shared`).
  std::vector<int> shared;  // local ids of nodes shared with another rank, ascending
  std::vector<int> sharer_first, sharers;
};

// The owner of every global node: the lowest rank whose elements touch it.
std::vector<int> node_owners(const ModelMesh& mesh, const std::vector<int>& element_part,
                             int n_ranks);

// Per rank: the nodes it shares with others and its neighbours (what make_subdomain would give,
// without building the local models).
struct HaloSize {
  int shared_nodes = 0;
  int neighbours = 0;
  long neighbour_node_pairs = 0;  // sum over neighbours of the nodes shared with each
};
std::vector<HaloSize> halo_sizes(const ModelMesh& mesh, const std::vector<int>& element_part,
                                 int n_ranks);

// The subdomain of `rank`. Surface loads are kept on the nodes the rank owns only (their sum over
// ranks is the global load), and on a rigid body's replicas; fixed nodes and initial velocities
// on every local copy. A rigid body is whole on every rank (its elements are never stepped): rank
// 0 owns its nodes, the others hold replicas of them after their copies, which no halo exchange
// touches. Every rank steps it alike from the same complete forces (the replicated contact gives
// every copy the whole contact force).
Subdomain make_subdomain(const Model& global, const std::vector<int>& element_part, int n_ranks,
                         int rank);

}  // namespace ccm::distributed
