#include "engine/distributed/replicated_contact.hpp"

#include <mpi.h>

#include <algorithm>
#include <numeric>

namespace ccm::distributed {
namespace {

constexpr int kWidth = 9;  // x, v, a per node; masses travel once, apart

}  // namespace

std::vector<int> contact_region(const ModelMesh& mesh, bool whole_bodies) {
  if (whole_bodies) {
    std::vector<int> every(mesh.X.size());
    std::iota(every.begin(), every.end(), 0);
    return every;
  }
  std::vector<int> region;
  std::vector<char> on_boundary(mesh.X.size(), 0), in_region(mesh.X.size(), 0);
  for (const Body& b : mesh.bodies)
    for (const Triangle& t : b.boundary)
      for (int n : t) on_boundary[static_cast<size_t>(n)] = 1;
  for (const Tet& t : mesh.tets) {
    const bool touches =
        std::any_of(t.begin(), t.end(), [&](int n) { return on_boundary[static_cast<size_t>(n)]; });
    if (touches)
      for (int n : t) in_region[static_cast<size_t>(n)] = 1;
  }
  for (size_t n = 0; n < in_region.size(); ++n)
    if (in_region[n] || on_boundary[n]) region.push_back(static_cast<int>(n));
  return region;
}

ReplicatedContact::ReplicatedContact(ContactModel& inner, ContactPhases phases,
                                     const std::vector<int>& region, const Subdomain& subdomain,
                                     const std::vector<int>& owners, const ModelMesh& global_mesh,
                                     const std::vector<int>& fixed_nodes, PhaseTimes& times)
    : ContactModel(inner.name()),
      inner_(inner), phases_(phases), times_(times), fixed_(global_mesh.X.size(), 0) {
  for (int n : fixed_nodes) fixed_[static_cast<size_t>(n)] = 1;
  std::vector<int> local_of(global_mesh.X.size(), -1);
  for (size_t l = 0; l < subdomain.global_node.size(); ++l)
    local_of[static_cast<size_t>(subdomain.global_node[l])] = static_cast<int>(l);
  std::vector<std::vector<int>> owned_by(static_cast<size_t>(subdomain.n_ranks));
  for (int g : region) {
    owned_by[static_cast<size_t>(owners[static_cast<size_t>(g)])].push_back(g);
    const int l = local_of[static_cast<size_t>(g)];
    if (l >= 0) local_copies_.push_back({l, g});
  }
  for (int g : owned_by[static_cast<size_t>(subdomain.rank)])
    owned_local_.push_back(local_of[static_cast<size_t>(g)]);
  for (const std::vector<int>& list : owned_by) {
    counts_.push_back(kWidth * static_cast<int>(list.size()));
    displs_.push_back(kWidth * static_cast<int>(gathered_global_.size()));
    gathered_global_.insert(gathered_global_.end(), list.begin(), list.end());
  }
  const size_t n = global_mesh.X.size();
  view_.X = global_mesh.X;
  view_.x = global_mesh.X;
  view_.v.assign(n, Vec3::Zero());
  view_.a.assign(n, Vec3::Zero());
  view_.f.assign(n, Vec3::Zero());
  view_.m_lumped.assign(n, 0.0);
  view_.inv_m.assign(n, 0.0);
}

void ReplicatedContact::gather(const State& local) const {
  view_.t = local.t;
  if (view_current_) return;
  ScopedTimer timer(times_.communication);
  const int n_ranks = static_cast<int>(counts_.size());
  if (!masses_known_) {  // assembled masses: once
    std::vector<double> mine, all(gathered_global_.size());
    std::vector<int> counts(static_cast<size_t>(n_ranks)), displs(static_cast<size_t>(n_ranks));
    for (int q = 0; q < n_ranks; ++q) {
      counts[static_cast<size_t>(q)] = counts_[static_cast<size_t>(q)] / kWidth;
      displs[static_cast<size_t>(q)] = displs_[static_cast<size_t>(q)] / kWidth;
    }
    for (int l : owned_local_) mine.push_back(local.m_lumped[static_cast<size_t>(l)]);
    MPI_Allgatherv(mine.data(), static_cast<int>(mine.size()), MPI_DOUBLE, all.data(),
                   counts.data(), displs.data(), MPI_DOUBLE, MPI_COMM_WORLD);
    for (size_t k = 0; k < gathered_global_.size(); ++k) {
      const auto g = static_cast<size_t>(gathered_global_[k]);
      view_.m_lumped[g] = all[k];
      view_.inv_m[g] = 1.0 / all[k];
    }
    masses_known_ = true;
  }
  std::vector<double> mine(kWidth * owned_local_.size()), all(kWidth * gathered_global_.size());
  for (size_t k = 0; k < owned_local_.size(); ++k) {
    const auto l = static_cast<size_t>(owned_local_[k]);
    double* p = mine.data() + kWidth * k;
    for (int c = 0; c < 3; ++c) {
      p[c] = local.x[l][c];
      p[3 + c] = local.v[l][c];
      p[6 + c] = local.a[l][c];
    }
  }
  ++times_.collectives;
  ++times_.region_gathers;
  MPI_Allgatherv(mine.data(), static_cast<int>(mine.size()), MPI_DOUBLE, all.data(), counts_.data(),
                 displs_.data(), MPI_DOUBLE, MPI_COMM_WORLD);
  for (size_t k = 0; k < gathered_global_.size(); ++k) {
    const auto g = static_cast<size_t>(gathered_global_[k]);
    const double* p = all.data() + kWidth * k;
    view_.x[g] = Vec3(p[0], p[1], p[2]);
    view_.v[g] = Vec3(p[3], p[4], p[5]);
    view_.a[g] = Vec3(p[6], p[7], p[8]);
  }
  view_current_ = true;
}

void ReplicatedContact::scatter(State& local) const {
  for (const auto& [l, g] : local_copies_) {
    local.x[static_cast<size_t>(l)] = view_.x[static_cast<size_t>(g)];
    local.v[static_cast<size_t>(l)] = view_.v[static_cast<size_t>(g)];
    local.a[static_cast<size_t>(l)] = view_.a[static_cast<size_t>(g)];
  }
}

// Called first in a step, with the state at t_n (gathered at the last end_step, or now).
ContactStepBound ReplicatedContact::step_bound(const State& state) const {
  gather(state);
  ScopedTimer timer(times_.contact);
  return inner_.step_bound(view_);
}

void ReplicatedContact::begin_step(const State& state, double dt) {
  gather(state);
  {
    ScopedTimer timer(times_.contact);
    inner_.begin_step(view_, dt);
  }
  view_current_ = false;  // the predictor moves every node next
}

// The forces on the region nodes: each rank adds them to its own copies, after the halo
// exchange, so they are counted once per copy, never summed across ranks.
void ReplicatedContact::add_forces(State& state) {
  if (!phases_.adds_forces) return;
  gather(state);
  {
    ScopedTimer timer(times_.contact);
    for (int g : gathered_global_) view_.f[static_cast<size_t>(g)].setZero();
    inner_.add_forces(view_);
  }
  for (const auto& [l, g] : local_copies_)
    state.f[static_cast<size_t>(l)] += view_.f[static_cast<size_t>(g)];
  view_current_ = false;  // the accelerations change next
}

void ReplicatedContact::correct(State& state, double dt) {
  if (!phases_.corrects) return;
  view_current_ = false;  // a_{n+1} is new
  gather(state);
  {
    ScopedTimer timer(times_.contact);
    inner_.correct(view_, dt);
  }
  scatter(state);
  view_current_ = false;  // boundary conditions and the velocity correction follow
}

// What the integrator does after the contact correction (engine/solver/explicit_integrator.cpp:
// the fixed nodes, then v_{n+1} = v* + dt/2 a_{n+1}; a partitioned run has no kinematic
// constraints), done on the view with the same arithmetic: the view then holds the state at
// t_{n+1} bit for bit, without a second gather.
void ReplicatedContact::finish_step(double dt) {
  const double half_dt = 0.5 * dt;
  for (int n : gathered_global_) {
    const auto g = static_cast<size_t>(n);
    if (fixed_[g]) {
      view_.x[g] = view_.X[g];
      view_.v[g].setZero();
      view_.a[g].setZero();
    }
    view_.v[g] += half_dt * view_.a[g];
  }
}

// The state at t_{n+1}, for end_step and the next step's limit and begin_step: a constraint-type
// model's view is advanced in place after its correction; a penalty model's is gathered (its
// accelerations a_{n+1} include the internal forces, known only to the owners).
void ReplicatedContact::end_step(const State& state, double dt) {
  view_current_ = false;
  if (phases_.corrects && !phases_.adds_forces) {
    finish_step(dt);
    view_current_ = true;
  }
  gather(state);
  ScopedTimer timer(times_.contact);
  inner_.end_step(view_, dt);
  ledger_ = inner_.ledger();
}

}  // namespace ccm::distributed
