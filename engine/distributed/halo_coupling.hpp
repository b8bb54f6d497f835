// The integrator's coupling to the other subdomains over MPI (engine/solver/domain_coupling.hpp):
// non-blocking exchange of shared-node partial sums with the neighbouring ranks only, global
// reductions in rank order (the same bits on every rank), and output samples gathered on rank 0.
#pragma once

#include <span>
#include <vector>

#include "engine/distributed/phase_times.hpp"
#include "engine/distributed/subdomain.hpp"
#include "engine/solver/explicit_integrator.hpp"

namespace ccm::distributed {

class HaloCoupling final : public DomainCoupling {
 public:
  // owners: the owner rank of every global node. history / on_sample: rank 0's recorders (may be
  // null/empty), fed with the global state. samples_wanted: whether rank 0 has any recorder, the
  // same on every rank; without one, a sample gathers nothing (the serial run's sample does
  // nothing then either).
  HaloCoupling(const Subdomain& subdomain, const std::vector<int>& owners,
               const ModelMesh& global_mesh, HistoryRecorder* history, SampleFn on_sample,
               bool samples_wanted, PhaseTimes& times);

  int owned_nodes() const override { return d_.owned_nodes; }
  void assemble(std::span<double> per_node, int width) override;
  void min_over_domains(std::span<double> values) override;
  void sum_over_domains(std::span<double> values) override;
  void sample(const State& local, std::span<const double> body_internal_energy) override;

 private:
  const Subdomain& d_;
  HistoryRecorder* history_;
  SampleFn on_sample_;
  PhaseTimes& times_;
  std::vector<std::vector<double>> send_, recv_;
  std::vector<double> own_;          // this rank's partial sums at its shared nodes
  std::vector<int> term_neighbour_;  // per sharer term: neighbour index, -1 for this rank
  std::vector<int> term_position_;   // its position in that neighbour's list (or shared)
  std::vector<int> gather_counts_, gather_displs_;  // owned nodes per rank (rank 0's gather)
  std::vector<int> gathered_global_;  // rank order of the gathered owned nodes: global ids
  State global_;                      // rank 0: the gathered state
  bool samples_wanted_ = true;
  bool first_sample_ = true;
};

}  // namespace ccm::distributed
