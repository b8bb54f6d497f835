// A run of one scene on all the ranks of `mpirun -np N ccm run SCENE` (docs/parallel.md
// "Distributed memory (METIS + MPI)"): the mesh is cut by METIS into one subdomain per rank, each
// rank steps its own with the serial integrator, coupled to its neighbours by halo exchanges of
// shared-node forces, to all by reductions of the step and the energies, and the contact region
// is replicated. Outputs (history, on_sample) are fed on rank 0 only.
//
// This header is MPI-free: MPI stays private to ccm_distributed.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "engine/distributed/replicated_contact.hpp"
#include "engine/solver/explicit_integrator.hpp"

namespace ccm::distributed {

// This process's rank and the number of ranks (MPI must be initialised; 0 and 1 otherwise).
int world_rank();
int world_size();

// What the partition and its communication cost; per rank where a vector, else rank 0's.
struct PartitionReport {
  int ranks = 1;
  double imbalance = 0.0;  // max part cost / mean - 1
  long cut_faces = 0;
  std::vector<int> owned_nodes, halo_nodes, neighbours, elements;  // per rank
  int contact_region_nodes = 0;
  // Per rank: the step loop's wall time and its communication and contact parts [s], and the
  // same in thread CPU time.
  std::vector<double> step_seconds, communication_seconds, contact_seconds;
  std::vector<double> step_cpu_seconds, communication_cpu_seconds, contact_cpu_seconds;
  // Per rank, parts of the communication's wall time: halo exchanges, the contact's gathers and
  // joins.
  std::vector<double> halo_seconds, contact_communication_seconds;
  std::vector<long> messages, message_doubles, collectives;  // per rank, whole run
  long region_gathers = 0;                                   // contact region gathers, whole run
};

// Why a model cannot run partitioned (a body of nodal-pressure tets: its nodal volumes would need
// the neighbours' share at every shared node before the pressures), or nothing.
std::optional<std::string> partition_refusal(const Model& global);

// Every rank calls it with the same global model and options (contact and constraints: the rank's
// own copies of the global ones, replicated_contact.hpp, replicated_constraint.hpp). The summary
// is the global one, the same on every rank. Throws std::invalid_argument for what a partitioned
// run does not support (state loads, partition_refusal).
RunSummary run_partitioned(const Model& global, const RunOptions& options,
                           PartitionReport* report = nullptr);

}  // namespace ccm::distributed
