#include "engine/distributed/distributed_run.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <memory>
#include <stdexcept>

#include "engine/distributed/halo_coupling.hpp"
#include "engine/distributed/partition.hpp"
#include "engine/distributed/replicated_constraint.hpp"
#include "engine/distributed/subdomain.hpp"

namespace ccm::distributed {

int world_rank() {
  int initialised = 0, rank = 0;
  MPI_Initialized(&initialised);
  if (initialised) MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

int world_size() {
  int initialised = 0, size = 1;
  MPI_Initialized(&initialised);
  if (initialised) MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size;
}

namespace {

template <typename T>
std::vector<T> gather_all(T value, MPI_Datatype type) {
  std::vector<T> all(static_cast<size_t>(world_size()));
  MPI_Allgather(&value, 1, type, all.data(), 1, type, MPI_COMM_WORLD);
  return all;
}

void fill_report(const Subdomain& d, const std::vector<int>& part, const ModelMesh& mesh,
                 const PhaseTimes& times, const RunSummary& local, int region_nodes,
                 PartitionReport& r) {
  const PartitionQuality q = measure_partition(mesh, part, d.n_ranks);
  r.ranks = d.n_ranks;
  r.imbalance = q.imbalance;
  r.cut_faces = q.cut_faces;
  r.owned_nodes = gather_all(d.owned_nodes, MPI_INT);
  r.halo_nodes = gather_all(static_cast<int>(d.shared.size()), MPI_INT);
  r.neighbours = gather_all(static_cast<int>(d.neighbours.size()), MPI_INT);
  r.elements = gather_all(d.model.mesh.n_elements(), MPI_INT);
  r.contact_region_nodes = region_nodes;
  r.step_seconds = gather_all(local.step_wall_seconds, MPI_DOUBLE);
  r.communication_seconds = gather_all(times.communication.wall, MPI_DOUBLE);
  r.contact_seconds = gather_all(times.contact.wall, MPI_DOUBLE);
  r.halo_seconds = gather_all(times.halo.wall, MPI_DOUBLE);
  r.contact_communication_seconds = gather_all(times.contact_communication.wall, MPI_DOUBLE);
  r.step_cpu_seconds = gather_all(local.step_cpu_seconds, MPI_DOUBLE);
  r.communication_cpu_seconds = gather_all(times.communication.cpu, MPI_DOUBLE);
  r.contact_cpu_seconds = gather_all(times.contact.cpu, MPI_DOUBLE);
  r.messages = gather_all(times.messages, MPI_LONG);
  r.message_doubles = gather_all(times.message_doubles, MPI_LONG);
  r.collectives = gather_all(times.collectives, MPI_LONG);
  r.region_gathers = times.region_gathers;
}

}  // namespace

std::optional<std::string> partition_refusal(const Model& global) {
  for (const Body& b : global.mesh.bodies)
    if (b.element == ElementKind::nodal_pressure && !b.rigid)
      return fmt::format(
          "a run partitioned over MPI ranks does not support element = \"nodal_pressure\" yet "
          "(body '{}'): run it on one rank (threads still apply), or use the linear tet",
          b.name);
  return std::nullopt;
}

RunSummary run_partitioned(const Model& global, const RunOptions& options,
                           PartitionReport* report) {
  if (!options.loads.empty())
    throw std::invalid_argument("a partitioned run supports no state loads yet");
  if (auto why = partition_refusal(global)) throw std::invalid_argument(*why);
  const int rank = world_rank(), size = world_size();
  const std::vector<int> part = partition_elements(global.mesh, size);
  const std::vector<int> owners = node_owners(global.mesh, part, size);
  const Subdomain d = make_subdomain(global, part, size, rank);
  PhaseTimes times;
  HaloCoupling coupling(d, owners, global.mesh, rank == 0 ? options.history : nullptr,
                        rank == 0 ? options.on_sample : SampleFn{},
                        options.history != nullptr || static_cast<bool>(options.on_sample), times);
  std::vector<int> constrained;  // every joint's nodes
  for (const KinematicConstraint* c : options.constraints)
    constrained.insert(constrained.end(), c->nodes().begin(), c->nodes().end());
  std::unique_ptr<ReplicatedContact> replicated;
  if (options.contact)
    replicated = std::make_unique<ReplicatedContact>(*options.contact, contact_region(global.mesh),
                                                     d, owners, global.mesh, global.bcs.fixed_nodes,
                                                     times, constrained);
  std::vector<std::unique_ptr<ReplicatedConstraint>> constraints;
  RunOptions local = options;
  local.constraints.clear();
  for (KinematicConstraint* c : options.constraints) {
    constraints.push_back(
        std::make_unique<ReplicatedConstraint>(*c, d, owners, global.mesh, times));
    local.constraints.push_back(constraints.back().get());
  }
  local.coupling = &coupling;
  local.contact = replicated.get();
  local.history = nullptr;
  local.on_sample = {};
  if (rank != 0) local.progress = {};
  MPI_Barrier(MPI_COMM_WORLD);  // every rank has built its subdomain: the run starts together
  RunSummary summary = run_explicit(d.model, local);
  if (report)
    fill_report(d, part, global.mesh, times, summary, replicated ? replicated->region_nodes() : 0,
                *report);
  // The global counts, and the wall times of the slowest rank.
  summary.n_nodes = global.mesh.n_nodes();
  summary.n_elements = global.mesh.n_elements();
  double walls[3] = {summary.wall_seconds, summary.step_wall_seconds, summary.step_cpu_seconds};
  MPI_Allreduce(MPI_IN_PLACE, walls, 3, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  summary.wall_seconds = walls[0];
  summary.step_wall_seconds = walls[1];
  summary.step_cpu_seconds = walls[2];
  if (summary.steps > 0 && summary.n_elements > 0)
    summary.ns_per_element_step =
        1e9 * summary.step_wall_seconds / (static_cast<double>(summary.steps) * summary.n_elements);
  return summary;
}

}  // namespace ccm::distributed
