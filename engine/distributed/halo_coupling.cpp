#include "engine/distributed/halo_coupling.hpp"

#include <mpi.h>

#include <algorithm>
#include <stdexcept>

#include "engine/distributed/node_gather.hpp"

namespace ccm::distributed {
namespace {

constexpr int kHaloTag = 17;
constexpr int kSampleWidth = kNodeStateWidth;  // x, v, a, m per node

int communicator_size() {
  int n = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}

}  // namespace

HaloCoupling::HaloCoupling(const Subdomain& subdomain, const std::vector<int>& owners,
                           const ModelMesh& global_mesh, HistoryRecorder* history,
                           SampleFn on_sample, bool samples_wanted, PhaseTimes& times)
    : d_(subdomain),
      history_(history),
      on_sample_(std::move(on_sample)),
      times_(times),
      samples_wanted_(samples_wanted) {
  if (communicator_size() != d_.n_ranks)
    throw std::logic_error("HaloCoupling: the subdomain was made for another number of ranks");
  send_.resize(d_.neighbours.size());
  recv_.resize(d_.neighbours.size());
  // Where each sharer's partial sum of each shared node is found, in ascending sharer rank.
  std::vector<int> shared_index(d_.global_node.size(), -1);
  for (size_t k = 0; k < d_.shared.size(); ++k)
    shared_index[static_cast<size_t>(d_.shared[k])] = static_cast<int>(k);
  term_neighbour_.assign(d_.sharers.size(), -1);
  term_position_.assign(d_.sharers.size(), -1);
  for (size_t j = 0; j < d_.neighbours.size(); ++j) {
    const Neighbour& nb = d_.neighbours[j];
    for (size_t p = 0; p < nb.nodes.size(); ++p) {
      const auto k = static_cast<size_t>(shared_index[static_cast<size_t>(nb.nodes[p])]);
      for (int t = d_.sharer_first[k]; t < d_.sharer_first[k + 1]; ++t)
        if (d_.sharers[static_cast<size_t>(t)] == nb.rank) {
          term_neighbour_[static_cast<size_t>(t)] = static_cast<int>(j);
          term_position_[static_cast<size_t>(t)] = static_cast<int>(p);
        }
    }
  }
  for (size_t k = 0; k < d_.shared.size(); ++k)
    for (int t = d_.sharer_first[k]; t < d_.sharer_first[k + 1]; ++t)
      if (d_.sharers[static_cast<size_t>(t)] == d_.rank)
        term_position_[static_cast<size_t>(t)] = static_cast<int>(k);
  // Rank 0 gathers the owned nodes of every rank, each in ascending global id.
  gather_counts_.assign(static_cast<size_t>(d_.n_ranks), 0);
  std::vector<std::vector<int>> owned_by(static_cast<size_t>(d_.n_ranks));
  for (size_t n = 0; n < owners.size(); ++n)
    if (owners[n] >= 0) owned_by[static_cast<size_t>(owners[n])].push_back(static_cast<int>(n));
  gather_displs_.assign(static_cast<size_t>(d_.n_ranks), 0);
  for (int q = 0; q < d_.n_ranks; ++q) {
    const auto& list = owned_by[static_cast<size_t>(q)];
    gather_counts_[static_cast<size_t>(q)] = kSampleWidth * static_cast<int>(list.size());
    gather_displs_[static_cast<size_t>(q)] =
        kSampleWidth * static_cast<int>(gathered_global_.size());
    gathered_global_.insert(gathered_global_.end(), list.begin(), list.end());
  }
  if (d_.rank == 0) global_ = global_view(global_mesh);
}

// f_i = sum over the ranks touching i, in ascending rank, of their partial sums: every rank
// evaluates the same expression, so every copy of a node holds the same bits.
void HaloCoupling::assemble(std::span<double> per_node, int width) {
  ScopedTimer timer(times_.communication), halo_timer(times_.halo);
  const auto w = static_cast<size_t>(width);
  std::vector<MPI_Request> requests;
  requests.reserve(2 * d_.neighbours.size());
  for (size_t j = 0; j < d_.neighbours.size(); ++j) {
    recv_[j].resize(w * d_.neighbours[j].nodes.size());
    requests.emplace_back();
    MPI_Irecv(recv_[j].data(), static_cast<int>(recv_[j].size()), MPI_DOUBLE, d_.neighbours[j].rank,
              kHaloTag, MPI_COMM_WORLD, &requests.back());
  }
  for (size_t j = 0; j < d_.neighbours.size(); ++j) {
    const std::vector<int>& nodes = d_.neighbours[j].nodes;
    send_[j].resize(w * nodes.size());
    for (size_t p = 0; p < nodes.size(); ++p)
      for (size_t c = 0; c < w; ++c)
        send_[j][w * p + c] = per_node[w * static_cast<size_t>(nodes[p]) + c];
    requests.emplace_back();
    MPI_Isend(send_[j].data(), static_cast<int>(send_[j].size()), MPI_DOUBLE, d_.neighbours[j].rank,
              kHaloTag, MPI_COMM_WORLD, &requests.back());
    ++times_.messages;
    times_.message_doubles += static_cast<long>(send_[j].size());
  }
  own_.resize(w * d_.shared.size());
  for (size_t k = 0; k < d_.shared.size(); ++k)
    for (size_t c = 0; c < w; ++c)
      own_[w * k + c] = per_node[w * static_cast<size_t>(d_.shared[k]) + c];
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  for (size_t k = 0; k < d_.shared.size(); ++k) {
    const auto node = static_cast<size_t>(d_.shared[k]);
    for (size_t c = 0; c < w; ++c) {
      double sum = 0.0;
      for (int t = d_.sharer_first[k]; t < d_.sharer_first[k + 1]; ++t) {
        const auto tt = static_cast<size_t>(t);
        const auto p = static_cast<size_t>(term_position_[tt]);
        const int j = term_neighbour_[tt];
        sum += j < 0 ? own_[w * p + c] : recv_[static_cast<size_t>(j)][w * p + c];
      }
      per_node[w * node + c] = sum;
    }
  }
}

void HaloCoupling::min_over_domains(std::span<double> values) {
  ScopedTimer timer(times_.communication);
  ++times_.collectives;
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_MIN,
                MPI_COMM_WORLD);
}

// Gathered, then summed in rank order on every rank: the same bits everywhere, whatever
// algorithm the MPI library's reduction would use.
void HaloCoupling::sum_over_domains(std::span<double> values) {
  ScopedTimer timer(times_.communication);
  ++times_.collectives;
  std::vector<double> all(values.size() * static_cast<size_t>(d_.n_ranks));
  MPI_Allgather(values.data(), static_cast<int>(values.size()), MPI_DOUBLE, all.data(),
                static_cast<int>(values.size()), MPI_DOUBLE, MPI_COMM_WORLD);
  for (size_t i = 0; i < values.size(); ++i) {
    double sum = 0.0;
    for (size_t q = 0; q < static_cast<size_t>(d_.n_ranks); ++q) sum += all[q * values.size() + i];
    values[i] = sum;
  }
}

void HaloCoupling::sample(const State& local, std::span<const double> body_internal_energy) {
  // The integrator samples first when its step loop starts: the phase times count from there
  // (set-up and the first evaluation are not part of a step).
  if (first_sample_) {
    times_ = PhaseTimes{};
    first_sample_ = false;
  }
  if (!samples_wanted_) return;
  std::vector<double> mine(kSampleWidth * static_cast<size_t>(d_.owned_nodes));
  for (size_t l = 0; l < static_cast<size_t>(d_.owned_nodes); ++l)
    pack_node_state(local, l, mine.data() + kSampleWidth * l);
  std::vector<double> all;
  {
    ScopedTimer timer(times_.communication);
    ++times_.collectives;
    if (d_.rank == 0) all.resize(kSampleWidth * gathered_global_.size());
    MPI_Gatherv(mine.data(), static_cast<int>(mine.size()), MPI_DOUBLE, all.data(),
                gather_counts_.data(), gather_displs_.data(), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  }
  if (d_.rank != 0) return;
  for (size_t k = 0; k < gathered_global_.size(); ++k)
    unpack_node_state(all.data() + kSampleWidth * k, static_cast<size_t>(gathered_global_[k]),
                      global_);
  global_.t = local.t;
  global_.rigid = local.rigid;  // every rank steps the rigid bodies alike (subdomain.hpp)
  if (history_) history_->sample(global_, body_internal_energy);
  if (on_sample_) on_sample_(global_);
}

}  // namespace ccm::distributed
