// Strong scaling of a partitioned run (docs/parallel.md "Distributed memory (METIS + MPI)").
//   bench_partitioned_run SCENE --serial          the serial integrator (the reference time)
//   mpirun -np N bench_partitioned_run SCENE      the partitioned run on N ranks (N = 1 too),
//                                                 with its per-phase wall times
//   bench_partitioned_run SCENE --partitions 2,4,..,64   no run: METIS cut, halo sizes and
//                                                 neighbour counts per rank count (the model's
//                                                 inputs)
//   mpirun -np N bench_partitioned_run SCENE --alternate R
//                                                 R rounds, each the serial run on rank 0 (the
//                                                 other ranks asleep) then the partitioned run,
//                                                 back to back in one process
// Rank 0 prints one line of key=value pairs per run or partition.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_statistics.hpp"
#include "engine/distributed/distributed_run.hpp"
#include "engine/distributed/partition.hpp"
#include "engine/distributed/replicated_contact.hpp"
#include "engine/distributed/subdomain.hpp"
#include "run/parallel/rank_context.hpp"
#include "run/scene/scene_builder.hpp"
#include "run/scene/scene_file.hpp"

namespace {

using namespace ccm;

template <typename T>
T largest(const std::vector<T>& v) {
  return v.empty() ? T{} : *std::max_element(v.begin(), v.end());
}

// "a,b,..." with 4 decimals: a quantity per rank.
std::string per_rank(const std::vector<double>& v) {
  std::string s;
  for (size_t q = 0; q < v.size(); ++q) s += fmt::format("{}{:.4f}", q ? "," : "", v[q]);
  return s;
}

void print_partitions(const Model& model, const std::vector<int>& contact_region,
                      const std::string& list) {
  std::istringstream in(list);
  std::string item;
  while (std::getline(in, item, ',')) {
    const int parts = std::stoi(item);
    const std::vector<int> part = distributed::partition_elements(model.mesh, parts);
    const distributed::PartitionQuality q = distributed::measure_partition(model.mesh, part, parts);
    const auto halo = distributed::halo_sizes(model.mesh, part, parts);
    int shared = 0, neighbours = 0;
    long pairs = 0;
    for (const auto& h : halo) {
      shared = std::max(shared, h.shared_nodes);
      neighbours = std::max(neighbours, h.neighbours);
      pairs = std::max(pairs, h.neighbour_node_pairs);
    }
    fmt::print(
        "partitions={} elements={} nodes={} imbalance={:.4f} cut_faces={} halo_nodes_max={} "
        "neighbours_max={} halo_pairs_max={} contact_region={}\n",
        parts, model.mesh.n_elements(), model.mesh.n_nodes(), q.imbalance, q.cut_faces, shared,
        neighbours, pairs, contact_region.size());
    std::fflush(stdout);
  }
}

// The machine's speed drifts between minutes (docs/parallel.md, "Measured"), more than the
// effect measured; a round puts the serial reference and the partitioned run seconds apart, in
// one process, so that each round's ratio T_serial / (P T_P) compares runs on the same machine.
void alternate(const Scene& scene, const Model& model, const study::RankContext& ranks,
               int rounds) {
  std::vector<double> efficiency;
  for (int round = 1; round <= rounds; ++round) {
    RunOptions options;
    options.time = time_control(scene.time);
    options.monitor = scene.monitor;
    double serial = 0.0;
    if (ranks.is_root()) {
      ContactSetup contact = build_contact(scene, model);
      options.contact = contact.model.get();
      serial = run_explicit(model, options).step_wall_seconds;
    }
    ranks.barrier_asleep();  // the waiting ranks leave the machine to rank 0
    ContactSetup contact = build_contact(scene, model);
    options.contact = contact.model.get();
    const RunSummary s = distributed::run_partitioned(model, options, nullptr);
    if (!ranks.is_root()) continue;
    const double e = serial / (ranks.size() * s.step_wall_seconds);
    efficiency.push_back(e);
    fmt::print(
        "round={} ranks={} serial_step_s={:.4f} partitioned_step_s={:.4f} "
        "efficiency={:.1f}%\n",
        round, ranks.size(), serial, s.step_wall_seconds, 100.0 * e);
    std::fflush(stdout);
  }
  if (ranks.is_root())
    fmt::print("rounds={} median_efficiency={:.1f}% lowest={:.1f}% highest={:.1f}%\n", rounds,
               100.0 * bench::median(efficiency),
               100.0 * *std::min_element(efficiency.begin(), efficiency.end()),
               100.0 * *std::max_element(efficiency.begin(), efficiency.end()));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr,
                 "usage: [mpirun -np N] %s SCENE [--serial | --partitions P,P,... | "
                 "--alternate ROUNDS]\n",
                 argv[0]);
    return 2;
  }
  const study::RankContext ranks;
  const bool serial = argc > 2 && !std::strcmp(argv[2], "--serial");
  const bool partitions = argc > 3 && !std::strcmp(argv[2], "--partitions");
  const bool alternating = argc > 3 && !std::strcmp(argv[2], "--alternate");
  const Scene scene = parse_scene_file(argv[1]);
  const Model model = build_model(scene);
  ContactSetup contact = build_contact(scene, model);
  if (partitions) {
    const std::vector<int> region =
        contact.model ? distributed::contact_region(model.mesh) : std::vector<int>{};
    if (ranks.is_root()) print_partitions(model, region, argv[3]);
    return 0;
  }
  if (alternating) {
    alternate(scene, model, ranks, std::max(1, std::atoi(argv[3])));
    return 0;
  }
  RunOptions options;
  options.time = time_control(scene.time);
  options.monitor = scene.monitor;
  options.contact = contact.model.get();
  if (serial) {
    const RunSummary s = run_explicit(model, options);
    fmt::print(
        "mode=serial elements={} steps={} verdict={} step_s={:.4f} step_cpu_s={:.4f} "
        "ns_per_element_step={:.2f}\n",
        s.n_elements, s.steps, to_string(s.verdict), s.step_wall_seconds, s.step_cpu_seconds,
        s.ns_per_element_step);
    return 0;
  }
  distributed::PartitionReport r;
  const RunSummary s = distributed::run_partitioned(model, options, &r);
  if (!ranks.is_root()) return 0;
  // The slowest rank's phases: structure = step loop - communication - contact, in wall time and
  // in thread CPU time (the CPU time of the communication includes Open MPI's busy waiting).
  std::vector<double> structure(r.step_seconds.size()), structure_cpu(r.step_seconds.size());
  for (size_t q = 0; q < structure.size(); ++q) {
    structure[q] = r.step_seconds[q] - r.communication_seconds[q] - r.contact_seconds[q];
    structure_cpu[q] =
        r.step_cpu_seconds[q] - r.communication_cpu_seconds[q] - r.contact_cpu_seconds[q];
  }
  const double steps = std::max(1.0, static_cast<double>(s.steps));
  fmt::print(
      "mode=partitioned ranks={} elements={} steps={} verdict={} step_s={:.4f} "
      "structure_s={:.4f} contact_s={:.4f} communication_s={:.4f} structure_cpu_s={:.4f} "
      "contact_cpu_s={:.4f} imbalance={:.4f} cut_faces={} halo_nodes_max={} neighbours_max={} "
      "contact_region={} messages_per_step={:.2f} doubles_per_step={:.1f} "
      "collectives_per_step={:.2f} region_gathers_per_step={:.2f} structure_by_rank={} "
      "contact_by_rank={} halo_by_rank={} contact_communication_by_rank={} "
      "communication_by_rank={} elements_by_rank={} owned_nodes_by_rank={}\n",
      r.ranks, s.n_elements, s.steps, to_string(s.verdict), s.step_wall_seconds, largest(structure),
      largest(r.contact_seconds), largest(r.communication_seconds), largest(structure_cpu),
      largest(r.contact_cpu_seconds), r.imbalance, r.cut_faces, largest(r.halo_nodes),
      largest(r.neighbours), r.contact_region_nodes,
      static_cast<double>(largest(r.messages)) / steps,
      static_cast<double>(largest(r.message_doubles)) / steps,
      static_cast<double>(largest(r.collectives)) / steps,
      static_cast<double>(r.region_gathers) / steps, per_rank(structure),
      per_rank(r.contact_seconds), per_rank(r.halo_seconds),
      per_rank(r.contact_communication_seconds), per_rank(r.communication_seconds),
      fmt::join(r.elements, ","), fmt::join(r.owned_nodes, ","));
  return 0;
}
