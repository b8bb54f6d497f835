// Contact across partitions by replication (docs/parallel.md "Contact across partitions"): every
// rank holds a view of the contact region (the nodes the contact model reads or writes each step)
// in global numbering, runs the same deterministic contact model on it, and copies the result
// into the local copies it holds. Each constraint is so solved once per rank, identically, and no
// rank needs to know where a contact pair lies relative to the partition.
//
// The view follows the integrator instead of being gathered: it replays the predictor and the
// velocity correction on the region with the integrator's arithmetic (bit for bit), so a step
// gathers only the new accelerations a_{n+1} of the region from their owners (3 doubles a node;
// the whole state x, v, a once, at the start). The rest of the mesh is gathered only when the
// model asks for whole bodies, and loops the model splits are joined by a maximum over the ranks
// (replica_team.hpp).
#pragma once

#include <memory>
#include <vector>

#include "engine/contact/contact_model.hpp"
#include "engine/distributed/node_gather.hpp"
#include "engine/distributed/phase_times.hpp"
#include "engine/distributed/subdomain.hpp"

namespace ccm::distributed {

// The contact region of a mesh: every boundary node, the nodes a contact model reads every step
// (the other nodes of the elements a DCR projection re-evaluates are fetched when it does).
// Sorted global ids.
std::vector<int> contact_region(const ModelMesh& mesh);

class ReplicatedContact final : public ContactModel, public ReplicaTeam {
 public:
  // inner: the model built on the global mesh (every rank has its own, identical one).
  // fixed_nodes: the global model's. constrained_nodes: the nodes the run's kinematic
  // constraints (joints) move after the contact correction, in global ids; the view takes their
  // end-of-step state from their owners instead of finishing them itself.
  ReplicatedContact(ContactModel& inner, const std::vector<int>& region, const Subdomain& subdomain,
                    const std::vector<int>& owners, const ModelMesh& global_mesh,
                    const std::vector<int>& fixed_nodes, PhaseTimes& times,
                    const std::vector<int>& constrained_nodes = {});

  void begin_step(const State& state, double dt) override;
  void add_forces(State& state) override;
  void correct(State& state, double dt) override;
  // Takes the inner model's ledger (the monitor's checks read it).
  void end_step(const State& state, double dt) override;
  ContactStepBound step_bound(const State& state, double ceiling) const override;
  double corrected_elements_stable_dt() const override;
  // The inner model's impulses on held bodies: the same on every rank, as every rank steps the
  // rigid bodies alike.
  void add_held_impulses(std::vector<HeldImpulse>& per_body) const override {
    inner_.add_held_impulses(per_body);
  }
  // The nodes beyond the region, from their owners, for the rest of this step's correct().
  void make_whole_bodies_current() override;
  // The listed nodes beyond the region, from their owners, for the rest of this step's correct().
  void make_nodes_current(std::span<const int> nodes) override;
  int rank() const override { return rank_; }
  int size() const override { return size_; }
  void max_over_ranks(std::span<double> values) const override;
  std::vector<int> join_over_ranks(std::span<const int> mine) const override;

  int region_nodes() const { return static_cast<int>(region_.global.size()); }

 private:
  // Gathers `width` doubles a node of the plan: pack(local id, out) on this rank's nodes,
  // unpack(global id, in) on every node.
  template <typename Pack, typename Unpack>
  void allgather(const GatherPlan& plan, int width, Pack pack, Unpack unpack) const;
  void gather_state(const State& local) const;                     // x, v, a and m of all nodes
  void gather_accelerations(const State& local, double dt) const;  // a of the region
  void predict_node(size_t g, double dt, double half_dt) const;    // eq. 2.27-2.28 on node g
  void catch_up(double dt) const;                                  // replays the predictor when due
  void take_rigid_bodies(const State& local) const;  // rigid bodies' nodes and states from local
  void take_constrained(const State& local) const;   // the joints' nodes, from their owners
  void copy_to_local(size_t g, State& local) const;  // x, v, a of g into its local copy, if any
  void scatter(std::span<const int> nodes, State& local) const;  // x, v, a into the local copies
  void finish_step(double dt);  // the integrator's fixed nodes and velocity correction
  void finish_node(size_t g, double half_dt);
  void scatter_and_finish(State& local, double dt);
  // Runs a hook of the inner model in the contact's time; the team's communication within it
  // counts as communication.
  template <typename Hook>
  void contact_time(Hook hook) const;

  ContactModel& inner_;
  PhaseTimes& times_;
  int rank_ = 0, size_ = 1;
  GatherPlan region_, rest_;       // the contact region; every other node
  GatherPlan constrained_;         // the region's nodes a joint moves
  std::vector<int> local_of_;      // per global node: its local id here, or -1
  std::vector<int> owner_;         // per global node: its owner rank
  std::vector<char> current_;      // per global node: in the region, or fetched in this correct()
  std::vector<int> fetched_;       // the nodes make_nodes_current() fetched in this correct()
  std::vector<char> fixed_;        // per global node
  std::vector<int> rigid_region_;  // the region's nodes on rigid bodies (global ids)
  const State* local_ = nullptr;   // the local state of the correct() under way
  mutable std::vector<double> send_, receive_;
  mutable State view_;                // global numbering; the region is current
  mutable bool started_ = false;      // the view has been gathered once
  mutable bool predict_due_ = false;  // the integrator has predicted, the view not yet
  mutable double dt_ = 0.0;           // of the step under way
  bool rest_current_ = false;         // the rest was gathered in this correct()
  bool finished_ = false;             // correct() has finished the step in the view
};

}  // namespace ccm::distributed
