// Contact across partitions by replication (docs/parallel.md "Distributed memory"): every rank
// holds the whole contact region (the nodes the contact model reads or writes), gathers its
// owners' current values (MPI_Allgatherv of the region nodes each rank owns), runs the same
// deterministic contact model on it, and copies the result into the local copies it holds. Each
// constraint is so solved once per rank, identically, and no rank needs to know where a contact
// pair lies relative to the partition.
#pragma once

#include <memory>
#include <vector>

#include "engine/contact/contact_model.hpp"
#include "engine/distributed/phase_times.hpp"
#include "engine/distributed/subdomain.hpp"

namespace ccm::distributed {

// What a contact model does to the state: penalty-type models add forces (add_forces), constraint
// types correct positions and velocities (correct); the region is gathered only for those.
struct ContactPhases {
  bool adds_forces = false;
  bool corrects = false;
};

// The contact region of a mesh: every boundary node and every node of an element touching one
// (a DCR projection re-evaluates those elements), or every node when whole_bodies (a body-pair
// restitution acts on the rigid motion of whole bodies). Sorted global ids.
std::vector<int> contact_region(const ModelMesh& mesh, bool whole_bodies);

class ReplicatedContact final : public ContactModel {
 public:
  // inner: the model built on the global mesh (every rank has its own, identical one).
  // fixed_nodes: the global model's, sorted.
  ReplicatedContact(ContactModel& inner, ContactPhases phases, const std::vector<int>& region,
                    const Subdomain& subdomain, const std::vector<int>& owners,
                    const ModelMesh& global_mesh, const std::vector<int>& fixed_nodes,
                    PhaseTimes& times);

  void begin_step(const State& state, double dt) override;
  void add_forces(State& state) override;
  void correct(State& state, double dt) override;
  // Takes the inner model's ledger (the monitor's checks read it).
  void end_step(const State& state, double dt) override;
  ContactStepBound step_bound(const State& state) const override;

  int region_nodes() const { return static_cast<int>(gathered_global_.size()); }

 private:
  void gather(const State& local) const;  // the region's x, v, a (and m once) from their owners
  void scatter(State& local) const;       // the region's x, v, a into the local copies
  void finish_step(double dt);            // the integrator's rest of the step, on the view

  ContactModel& inner_;
  ContactPhases phases_;
  PhaseTimes& times_;
  std::vector<int> owned_local_;                   // region nodes this rank owns: local ids
  std::vector<int> gathered_global_;               // gathered order: global ids
  std::vector<int> counts_, displs_;               // per rank, in doubles
  std::vector<std::pair<int, int>> local_copies_;  // (local, global) of region nodes held here
  std::vector<char> fixed_;                        // per global node
  mutable State view_;                             // global numbering; the region is current
  mutable bool view_current_ = false;              // the view holds the local state's values
  mutable bool masses_known_ = false;
};

}  // namespace ccm::distributed
