// A kinematic constraint (a pin joint, a slide, track friction: engine/bc/) in a partitioned run
// (docs/parallel.md "Joints across partitions"): its nodes may lie on several ranks, and a pin
// couples all of them (the ring turns as one). Every rank gathers the constraint's nodes from
// their owners into a view in global numbering, applies the same constraint to it, and copies
// the result into the local copies it holds: each rank so holds the same constraint state
// (angle, rate, work) and its nodes the same bits, as the replicated contact does for contacts.
#pragma once

#include <vector>

#include "engine/bc/kinematic_constraint.hpp"
#include "engine/distributed/node_gather.hpp"
#include "engine/distributed/phase_times.hpp"
#include "engine/distributed/subdomain.hpp"

namespace ccm::distributed {

class ReplicatedConstraint final : public KinematicConstraint {
 public:
  // inner: the constraint built on the global model (every rank has its own, identical one).
  ReplicatedConstraint(KinematicConstraint& inner, const Subdomain& subdomain,
                       const std::vector<int>& owners, const ModelMesh& global_mesh,
                       PhaseTimes& times);

  std::string_view name() const override { return inner_.name(); }
  const std::vector<int>& nodes() const override { return inner_.nodes(); }
  void initialise(State& local) override;
  void apply(State& local, double dt) override;
  // The same on every rank: the integrator adds it once, after its sums over the domains.
  double work() const override { return inner_.work(); }

 private:
  void gather(const State& local);     // x, v, a, m of the constraint's nodes into the view
  void copy_back(State& local) const;  // x, v, a of its nodes into the local copies

  KinematicConstraint& inner_;
  PhaseTimes& times_;
  GatherPlan plan_;
  std::vector<int> local_of_;  // per node of plan_.global: its local id here, or -1
  State view_;                 // global numbering; the constraint's nodes are current
  std::vector<double> send_, receive_;
};

}  // namespace ccm::distributed
