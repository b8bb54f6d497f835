#include "engine/distributed/node_gather.hpp"

#include <mpi.h>

namespace ccm::distributed {

GatherPlan make_gather_plan(const std::vector<int>& nodes, const Subdomain& d,
                            const std::vector<int>& owners, const std::vector<int>& local_of) {
  std::vector<std::vector<int>> owned_by(static_cast<size_t>(d.n_ranks));
  for (int g : nodes) owned_by[static_cast<size_t>(owners[static_cast<size_t>(g)])].push_back(g);
  GatherPlan plan;
  for (int g : owned_by[static_cast<size_t>(d.rank)])
    plan.owned_local.push_back(local_of[static_cast<size_t>(g)]);
  for (const std::vector<int>& list : owned_by) {
    plan.counts.push_back(static_cast<int>(list.size()));
    plan.displs.push_back(static_cast<int>(plan.global.size()));
    plan.global.insert(plan.global.end(), list.begin(), list.end());
  }
  return plan;
}

void pack_node_state(const State& s, size_t local, double* p) {
  for (int c = 0; c < 3; ++c) {
    p[c] = s.x[local][c];
    p[3 + c] = s.v[local][c];
    p[6 + c] = s.a[local][c];
  }
  p[9] = s.m_lumped[local];
}

void unpack_node_state(const double* p, size_t global, State& view) {
  view.x[global] = Vec3(p[0], p[1], p[2]);
  view.v[global] = Vec3(p[3], p[4], p[5]);
  view.a[global] = Vec3(p[6], p[7], p[8]);
  view.m_lumped[global] = p[9];
  view.inv_m[global] = p[9] > 0.0 ? 1.0 / p[9] : 0.0;
}

State global_view(const ModelMesh& mesh) {
  const size_t n = mesh.X.size();
  State view;
  view.X = mesh.X;
  view.x = mesh.X;
  view.v.assign(n, Vec3::Zero());
  view.a.assign(n, Vec3::Zero());
  view.f.assign(n, Vec3::Zero());
  view.m_lumped.assign(n, 0.0);
  view.inv_m.assign(n, 0.0);
  return view;
}

void allgather_nodes(const GatherPlan& plan, int width, const std::vector<double>& send,
                     std::vector<double>& receive, PhaseTimes& times) {
  receive.resize(static_cast<size_t>(width) * plan.global.size());
  std::vector<int> counts(plan.counts), displs(plan.displs);
  for (int& c : counts) c *= width;
  for (int& d : displs) d *= width;
  ScopedTimer timer(times.communication);
  ++times.collectives;
  MPI_Allgatherv(send.data(), static_cast<int>(send.size()), MPI_DOUBLE, receive.data(),
                 counts.data(), displs.data(), MPI_DOUBLE, MPI_COMM_WORLD);
}

}  // namespace ccm::distributed
