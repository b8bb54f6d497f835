// How the explicit integrator runs on one subdomain of a partitioned mesh (engine/distributed/,
// docs/parallel.md "Distributed memory"). A serial run passes no coupling and pays nothing.
//
// The local model of a subdomain holds its own elements and every node they touch. Nodes
// [0, owned_nodes()) are the subdomain's own; the rest are copies of nodes another subdomain owns.
// Every copy of a node is advanced by the same arithmetic from the same assembled force, so all
// copies stay bit-identical; sums over nodes (kinetic energy, work) count owned nodes only.
#pragma once

#include <span>
#include <vector>

#include "engine/core/state.hpp"

namespace ccm {

class DomainCoupling {
 public:
  virtual ~DomainCoupling() = default;

  // Nodes [0, owned_nodes()) of the local model are owned by this subdomain.
  virtual int owned_nodes() const = 0;
  // Completes per-node partial sums at the nodes shared with neighbouring subdomains (width
  // doubles per node: 1 for masses, 3 for forces), summed in one fixed order on every side.
  virtual void assemble(std::span<double> per_node, int width) = 0;
  // Element-wise minimum / sum over all subdomains, the same result on every subdomain.
  virtual void min_over_domains(std::span<double> values) = 0;
  virtual void sum_over_domains(std::span<double> values) = 0;
  // An output sample: the local state (owned nodes) and the per-body internal energy (already
  // summed over subdomains) go to whoever records the history.
  virtual void sample(const State& local, std::span<const double> body_internal_energy) = 0;
};

}  // namespace ccm
