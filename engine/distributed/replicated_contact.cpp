#include "engine/distributed/replicated_contact.hpp"

#include <mpi.h>

#include <algorithm>

namespace ccm::distributed {
namespace {

constexpr int kStateWidth = kNodeStateWidth;  // x, v, a, m per node: at the start, and the rest
constexpr int kAccelerationWidth = 3;         // a per node: every step

}  // namespace

std::vector<int> contact_region(const ModelMesh& mesh) {
  std::vector<int> region;
  std::vector<char> on_boundary(mesh.X.size(), 0);
  for (const Body& b : mesh.bodies)
    for (const Triangle& t : b.boundary)
      for (int n : t) on_boundary[static_cast<size_t>(n)] = 1;
  for (size_t n = 0; n < on_boundary.size(); ++n)
    if (on_boundary[n]) region.push_back(static_cast<int>(n));
  return region;
}

ReplicatedContact::ReplicatedContact(ContactModel& inner, const std::vector<int>& region,
                                     const Subdomain& subdomain, const std::vector<int>& owners,
                                     const ModelMesh& global_mesh,
                                     const std::vector<int>& fixed_nodes, PhaseTimes& times,
                                     const std::vector<int>& constrained_nodes)
    : ContactModel(inner.name(), inner.phases()),
      inner_(inner),
      times_(times),
      rank_(subdomain.rank),
      size_(subdomain.n_ranks),
      local_of_(global_mesh.X.size(), -1),
      owner_(owners),
      current_(global_mesh.X.size(), 0),
      fixed_(global_mesh.X.size(), 0) {
  for (int n : fixed_nodes) fixed_[static_cast<size_t>(n)] = 1;
  for (size_t l = 0; l < subdomain.global_node.size(); ++l)
    local_of_[static_cast<size_t>(subdomain.global_node[l])] = static_cast<int>(l);
  std::vector<char> in_region(global_mesh.X.size(), 0);
  for (int g : region) in_region[static_cast<size_t>(g)] = current_[static_cast<size_t>(g)] = 1;
  for (const Body& b : global_mesh.bodies)
    if (b.rigid)
      for (int g = b.first_node; g < b.first_node + b.n_nodes; ++g)
        if (in_region[static_cast<size_t>(g)]) rigid_region_.push_back(g);
  std::vector<int> rest;
  for (size_t g = 0; g < in_region.size(); ++g)
    if (!in_region[g]) rest.push_back(static_cast<int>(g));
  region_ = make_gather_plan(region, subdomain, owners, local_of_);
  std::vector<char> constrained(global_mesh.X.size(), 0);
  for (int g : constrained_nodes) constrained[static_cast<size_t>(g)] = 1;
  std::vector<int> constrained_region;
  for (int g : region)
    if (constrained[static_cast<size_t>(g)]) constrained_region.push_back(g);
  constrained_ = make_gather_plan(constrained_region, subdomain, owners, local_of_);
  rest_ = make_gather_plan(rest, subdomain, owners, local_of_);
  view_ = global_view(global_mesh);
  inner_.use_replica_team(*this);
}

template <typename Pack, typename Unpack>
void ReplicatedContact::allgather(const GatherPlan& plan, int width, Pack pack,
                                  Unpack unpack) const {
  const auto w = static_cast<size_t>(width);
  send_.resize(w * plan.owned_local.size());
  for (size_t k = 0; k < plan.owned_local.size(); ++k)
    pack(static_cast<size_t>(plan.owned_local[k]), send_.data() + w * k);
  {
    ScopedTimer contact_timer(times_.contact_communication);
    allgather_nodes(plan, width, send_, receive_, times_);
  }
  for (size_t k = 0; k < plan.global.size(); ++k)
    unpack(static_cast<size_t>(plan.global[k]), receive_.data() + w * k);
}

template <typename Hook>
void ReplicatedContact::contact_time(Hook hook) const {
  const Seconds communication_before = times_.communication;
  {
    ScopedTimer timer(times_.contact);
    hook();
  }
  times_.contact.wall -= times_.communication.wall - communication_before.wall;
  times_.contact.cpu -= times_.communication.cpu - communication_before.cpu;
}

void ReplicatedContact::max_over_ranks(std::span<double> values) const {
  ScopedTimer timer(times_.communication), contact_timer(times_.contact_communication);
  ++times_.collectives;
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_MAX,
                MPI_COMM_WORLD);
}

std::vector<int> ReplicatedContact::join_over_ranks(std::span<const int> mine) const {
  ScopedTimer timer(times_.communication), contact_timer(times_.contact_communication);
  times_.collectives += 2;
  const int count = static_cast<int>(mine.size());
  std::vector<int> counts(static_cast<size_t>(size_)), displs(static_cast<size_t>(size_), 0);
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  for (size_t q = 1; q < counts.size(); ++q) displs[q] = displs[q - 1] + counts[q - 1];
  std::vector<int> all(static_cast<size_t>(displs.back() + counts.back()));
  MPI_Allgatherv(mine.data(), count, MPI_INT, all.data(), counts.data(), displs.data(), MPI_INT,
                 MPI_COMM_WORLD);
  return all;
}

// Once, at the start: every node, so that the model knows every mass (it takes them at its first
// step, DCR's projection update included, which reaches into the bodies).
void ReplicatedContact::gather_state(const State& local) const {
  ++times_.region_gathers;
  for (const GatherPlan* plan : {&region_, &rest_})
    allgather(
        *plan, kStateWidth, [&](size_t l, double* p) { pack_node_state(local, l, p); },
        [&](size_t g, const double* p) { unpack_node_state(p, g, view_); });
}

// The region's a_{n+1} from their owners. When the predictor is still due, it is replayed in the
// same pass, node by node before the node's new acceleration is written (catch_up's arithmetic).
void ReplicatedContact::gather_accelerations(const State& local, double dt) const {
  ++times_.region_gathers;
  const bool predict = predict_due_;
  predict_due_ = false;
  const double half_dt = 0.5 * dt;
  allgather(
      region_, kAccelerationWidth,
      [&](size_t l, double* p) {
        for (int c = 0; c < 3; ++c) p[c] = local.a[l][c];
      },
      [&](size_t g, const double* p) {
        if (predict) predict_node(g, dt, half_dt);
        view_.a[g] = Vec3(p[0], p[1], p[2]);
      });
}

// x_{n+1} = x_n + dt v_n + dt^2/2 a_n ;  v* = v_n + dt/2 a_n   (eq. 2.27-2.28), on the region,
// written as the integrator's predictor (engine/solver/explicit_integrator.cpp) so that the view
// holds its result bit for bit.
void ReplicatedContact::predict_node(size_t g, double dt, double half_dt) const {
  view_.v[g] += half_dt * view_.a[g];
  view_.x[g] += dt * view_.v[g];
}

void ReplicatedContact::catch_up(double dt) const {
  if (!predict_due_) return;
  predict_due_ = false;
  const double half_dt = 0.5 * dt;
  for (int n : region_.global) predict_node(static_cast<size_t>(n), dt, half_dt);
}

// A rigid body's nodes follow its pose, not the nodal predictor and corrector the view replays:
// every rank steps the body alike and holds all its nodes (subdomain.hpp), so the view takes
// them, and the bodies' states, from the local state.
void ReplicatedContact::take_rigid_bodies(const State& local) const {
  if (local.rigid.empty()) return;
  view_.rigid = local.rigid;
  for (int n : rigid_region_) {
    const auto g = static_cast<size_t>(n);
    const auto l = static_cast<size_t>(local_of_[g]);
    view_.x[g] = local.x[l];
    view_.v[g] = local.v[l];
    view_.a[g] = local.a[l];
  }
}

// The integrator's joints (kinematic constraints) move their nodes after the contact correction
// (step 4): the view's finish of those nodes is not the integrator's, so at the end of a step
// their x, v, a come from their owners, whose state is then final.
void ReplicatedContact::take_constrained(const State& local) const {
  if (constrained_.global.empty()) return;
  allgather(
      constrained_, kStateWidth, [&](size_t l, double* p) { pack_node_state(local, l, p); },
      [&](size_t g, const double* p) { unpack_node_state(p, g, view_); });
}

void ReplicatedContact::copy_to_local(size_t g, State& local) const {
  const int l = local_of_[g];
  if (l < 0) return;
  local.x[static_cast<size_t>(l)] = view_.x[g];
  local.v[static_cast<size_t>(l)] = view_.v[g];
  local.a[static_cast<size_t>(l)] = view_.a[g];
}

void ReplicatedContact::scatter(std::span<const int> nodes, State& local) const {
  for (int n : nodes) copy_to_local(static_cast<size_t>(n), local);
}

// scatter(region_) and finish_step() in one pass over the region: each node is copied to its
// local copy, then finished in the view.
void ReplicatedContact::scatter_and_finish(State& local, double dt) {
  const double half_dt = 0.5 * dt;
  for (int n : region_.global) {
    const auto g = static_cast<size_t>(n);
    copy_to_local(g, local);
    finish_node(g, half_dt);
  }
  finished_ = true;
}

// Called first in a step, with the state at t_n (the view holds it, but at the first step).
ContactStepBound ReplicatedContact::step_bound(const State& state, double ceiling) const {
  view_.t = state.t;
  if (!started_) {
    gather_state(state);
    started_ = true;
  }
  take_rigid_bodies(state);
  ContactStepBound bound;
  contact_time([&] { bound = inner_.step_bound(view_, ceiling); });
  return bound;
}

// Every rank projects the same contacts on its replica: the same step on every rank.
double ReplicatedContact::corrected_elements_stable_dt() const {
  return inner_.corrected_elements_stable_dt();
}

void ReplicatedContact::begin_step(const State& state, double dt) {
  view_.t = state.t;
  if (!started_) {
    gather_state(state);
    started_ = true;
  }
  dt_ = dt;
  take_rigid_bodies(state);
  contact_time([&] { inner_.begin_step(view_, dt); });
  predict_due_ = true;  // the integrator predicts next
}

// The forces on the region nodes: each rank adds them to its own copies, after the halo
// exchange, so they are counted once per copy, never summed across ranks. The first call comes
// from the initial evaluation, before any step: the view is gathered for it.
void ReplicatedContact::add_forces(State& state) {
  if (!phases().adds_forces) return;
  view_.t = state.t;
  if (started_)
    catch_up(dt_);
  else
    gather_state(state);
  take_rigid_bodies(state);
  contact_time([&] {
    for (int g : region_.global) view_.f[static_cast<size_t>(g)].setZero();
    inner_.add_forces(view_);
  });
  for (int n : region_.global) {
    const int l = local_of_[static_cast<size_t>(n)];
    if (l >= 0) state.f[static_cast<size_t>(l)] += view_.f[static_cast<size_t>(n)];
  }
}

void ReplicatedContact::correct(State& state, double dt) {
  if (!phases().corrects) return;
  view_.t = state.t;
  local_ = &state;
  rest_current_ = false;
  contact_time([&] {
    gather_accelerations(state, dt);
    take_rigid_bodies(state);
    inner_.correct(view_, dt);
    if (rest_current_) scatter(rest_.global, state);
    scatter(fetched_, state);
    scatter_and_finish(state, dt);
  });
  for (int g : fetched_) current_[static_cast<size_t>(g)] = 0;
  fetched_.clear();
  local_ = nullptr;
}

void ReplicatedContact::make_whole_bodies_current() {
  if (rest_current_ || local_ == nullptr) return;
  allgather(  // a node fetched before keeps what the model did to it since
      rest_, kStateWidth, [&](size_t l, double* p) { pack_node_state(*local_, l, p); },
      [&](size_t g, const double* p) {
        if (!current_[g]) unpack_node_state(p, g, view_);
      });
  rest_current_ = true;
}

// Each listed node that is not current yet comes from its owner: rank q sends the ones it owns,
// in list order, so every rank knows where each node's values are in the joined buffer.
void ReplicatedContact::make_nodes_current(std::span<const int> nodes) {
  if (rest_current_ || local_ == nullptr) return;
  const size_t first = fetched_.size();
  for (int n : nodes)
    if (!current_[static_cast<size_t>(n)]) {
      current_[static_cast<size_t>(n)] = 1;
      fetched_.push_back(n);
    }
  const std::span<const int> wanted(fetched_.data() + first, fetched_.size() - first);
  if (wanted.empty()) return;  // the same on every rank: the lists and flags are replicated
  GatherPlan plan;
  plan.counts.assign(static_cast<size_t>(size_), 0);
  for (int g : wanted) {
    const int q = owner_[static_cast<size_t>(g)];
    ++plan.counts[static_cast<size_t>(q)];
    if (q == rank_) plan.owned_local.push_back(local_of_[static_cast<size_t>(g)]);
  }
  plan.displs.assign(static_cast<size_t>(size_), 0);
  for (size_t q = 1; q < plan.displs.size(); ++q)
    plan.displs[q] = plan.displs[q - 1] + plan.counts[q - 1];
  plan.global.resize(wanted.size());  // the wanted nodes in the joined (rank) order
  std::vector<int> next(plan.displs);
  for (int g : wanted) {
    const auto q = static_cast<size_t>(owner_[static_cast<size_t>(g)]);
    plan.global[static_cast<size_t>(next[q]++)] = g;
  }
  allgather(
      plan, kStateWidth, [&](size_t l, double* p) { pack_node_state(*local_, l, p); },
      [&](size_t g, const double* p) { unpack_node_state(p, g, view_); });
}

// What the integrator does after the contact correction (engine/solver/explicit_integrator.cpp:
// the fixed nodes, then v_{n+1} = v* + dt/2 a_{n+1}, eq. 2.31), done on the region of the view
// with the same arithmetic: the view then holds the state at t_{n+1} bit for bit, but at the
// joints' nodes (taken from their owners after it, take_constrained).
void ReplicatedContact::finish_node(size_t g, double half_dt) {
  if (fixed_[g]) {
    view_.x[g] = view_.X[g];
    view_.v[g].setZero();
    view_.a[g].setZero();
  }
  view_.v[g] += half_dt * view_.a[g];
}

void ReplicatedContact::finish_step(double dt) {
  const double half_dt = 0.5 * dt;
  for (int n : region_.global) finish_node(static_cast<size_t>(n), half_dt);
}

// The state at t_{n+1}, for end_step and the next step's limit and begin_step. A penalty model's
// accelerations a_{n+1} include the internal forces, known only to the owners: gathered here; a
// constraint model's were gathered for its correction.
void ReplicatedContact::end_step(const State& state, double dt) {
  view_.t = state.t;
  if (!finished_) {  // a constraint model's correct() has finished the view already
    contact_time([&] {
      gather_accelerations(state, dt);  // replays the predictor too if add_forces did not
      finish_step(dt);
    });
  }
  finished_ = false;
  contact_time([&] { take_constrained(state); });
  take_rigid_bodies(state);
  contact_time([&] { inner_.end_step(view_, dt); });
  ledger_ = inner_.ledger();
}

}  // namespace ccm::distributed
