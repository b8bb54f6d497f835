#include "engine/distributed/replicated_constraint.hpp"

#include <algorithm>

namespace ccm::distributed {
namespace {

constexpr int kWidth = 10;  // x, v, a, m per node

}  // namespace

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
  const size_t n = global_mesh.X.size();
  view_.X = global_mesh.X;
  view_.x = global_mesh.X;
  view_.v.assign(n, Vec3::Zero());
  view_.a.assign(n, Vec3::Zero());
  view_.f.assign(n, Vec3::Zero());
  view_.m_lumped.assign(n, 0.0);
  view_.inv_m.assign(n, 0.0);
}

void ReplicatedConstraint::gather(const State& local) {
  send_.resize(kWidth * plan_.owned_local.size());
  for (size_t k = 0; k < plan_.owned_local.size(); ++k) {
    const auto l = static_cast<size_t>(plan_.owned_local[k]);
    double* p = send_.data() + kWidth * k;
    for (int c = 0; c < 3; ++c) {
      p[c] = local.x[l][c];
      p[3 + c] = local.v[l][c];
      p[6 + c] = local.a[l][c];
    }
    p[9] = local.m_lumped[l];
  }
  allgather_nodes(plan_, kWidth, send_, receive_, times_);
  for (size_t k = 0; k < plan_.global.size(); ++k) {
    const auto g = static_cast<size_t>(plan_.global[k]);
    const double* p = receive_.data() + kWidth * k;
    view_.x[g] = Vec3(p[0], p[1], p[2]);
    view_.v[g] = Vec3(p[3], p[4], p[5]);
    view_.a[g] = Vec3(p[6], p[7], p[8]);
    view_.m_lumped[g] = p[9];
    view_.inv_m[g] = p[9] > 0.0 ? 1.0 / p[9] : 0.0;
  }
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
