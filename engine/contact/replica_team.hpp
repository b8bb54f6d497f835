// The ranks of a partitioned run that each hold the same replicated contact model
// (docs/parallel.md, "Contact across partitions"), as the model sees them. A serial run has no
// team: the model's state holds every node and it does every loop itself.
//
// A partitioned run keeps only the contact region current in the state its contact model sees.
// What the team offers the model:
//  - whole bodies on demand: DCR's body-pair restitution (docs/contact-restitution.md) takes the
//    rigid motion of whole bodies when an episode begins and changes it when it ends; the nodes
//    beyond the region are gathered only in those steps, never every step;
//  - listed nodes on demand: DCR's projection update (projection_update.hpp) re-evaluates the
//    elements around the nodes it moved, whose other nodes lie inside the bodies;
//  - a split of the loops whose result is a maximum (or a minimum, as the maximum of its
//    negative) or a list in item order: each rank takes its share of the items, and the ranks
//    take the maximum of their results, which is exact, or join their lists in rank order, which
//    is the item order. The result is the serial one bit for bit.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace ccm {

class ReplicaTeam {
 public:
  virtual ~ReplicaTeam() = default;
  // Called within ContactModel::correct(). Afterwards every node of the state the model was given
  // holds x_{n+1}, v*, a_{n+1} and its mass, and the model's changes to them are kept. Every rank
  // calls it at the same point (the replicated model decides alike).
  virtual void make_whole_bodies_current() = 0;
  // The same for the listed nodes only (global ids, any order, repeats allowed). Every rank calls
  // it at the same point with the same list.
  virtual void make_nodes_current(std::span<const int> nodes) = 0;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  // values[i] = the maximum of values[i] over the ranks, on every rank.
  virtual void max_over_ranks(std::span<double> values) const = 0;
  // Every rank's `mine`, joined in rank order, on every rank.
  virtual std::vector<int> join_over_ranks(std::span<const int> mine) const = 0;
};

// The items [begin, end) of n that a rank takes (all of them without a team): contiguous, in rank
// order.
struct ItemShare {
  std::size_t begin = 0, end = 0;
};

inline ItemShare share_of(const ReplicaTeam* team, std::size_t n) {
  if (team == nullptr) return {0, n};
  const auto rank = static_cast<std::size_t>(team->rank());
  const auto size = static_cast<std::size_t>(team->size());
  return {n * rank / size, n * (rank + 1) / size};
}

}  // namespace ccm
