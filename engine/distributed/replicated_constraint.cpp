#include "engine/distributed/replicated_constraint.hpp"

#include <algorithm>

namespace ccm::distributed {
ReplicatedConstraint::ReplicatedConstraint(KinematicConstraint& inner, const Subdomain& subdomain,
                                           const std::vector<int>& owners,
                                           const ModelMesh& global_mesh, PhaseTimes& times)
    : inner_(inner), times_(times) {
  std::vector<int> local_of(global_mesh.X.size(), -1);
  for (size_t l = 0; l < subdomain.global_node.size(); ++l)
    local_of[static_cast<size_t>(subdomain.global_node[l])] = static_cast<int>(l);
  std::vector<int> nodes = inner.nodes();
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  plan_ = make_gather_plan(nodes, subdomain, owners, local_of);
  for (int g : plan_.global) local_of_.push_back(local_of[static_cast<size_t>(g)]);
  view_ = global_view(global_mesh);
}

void ReplicatedConstraint::gather(const State& local) {
  send_.resize(kNodeStateWidth * plan_.owned_local.size());
  for (size_t k = 0; k < plan_.owned_local.size(); ++k)
    pack_node_state(local, static_cast<size_t>(plan_.owned_local[k]),
                    send_.data() + kNodeStateWidth * k);
  allgather_nodes(plan_, kNodeStateWidth, send_, receive_, times_);
  for (size_t k = 0; k < plan_.global.size(); ++k)
    unpack_node_state(receive_.data() + kNodeStateWidth * k, static_cast<size_t>(plan_.global[k]),
                      view_);
  view_.t = local.t;
}

void ReplicatedConstraint::copy_back(State& local) const {
  for (size_t k = 0; k < plan_.global.size(); ++k) {
    if (local_of_[k] < 0) continue;
    const auto g = static_cast<size_t>(plan_.global[k]);
    const auto l = static_cast<size_t>(local_of_[k]);
    local.x[l] = view_.x[g];
    local.v[l] = view_.v[g];
    local.a[l] = view_.a[g];
  }
}

void ReplicatedConstraint::initialise(State& local) {
  gather(local);
  inner_.initialise(view_);
  copy_back(local);
}

void ReplicatedConstraint::apply(State& local, double dt) {
  gather(local);
  inner_.apply(view_, dt);
  copy_back(local);
}

}  // namespace ccm::distributed
