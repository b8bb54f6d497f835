// The hook through which a contact model reads or writes every node of a body, not only its
// contact surface: DCR's body-pair restitution (docs/contact-restitution.md) takes the rigid
// motion of whole bodies when an episode begins and applies a rigid velocity change to them when
// it ends. A serial run's state holds every node and needs no hook. A partitioned run keeps only
// the contact region current in the state its contact model sees (docs/parallel.md, "Contact
// across partitions") and brings the other nodes in on demand, which is rare: it costs one gather
// of the rest of the mesh in the steps where an episode begins or ends, never a per-step one.
#pragma once

namespace ccm {

class WholeBodies {
 public:
  virtual ~WholeBodies() = default;
  // Called within ContactModel::correct(). Afterwards every node of the state the model was given
  // holds x_{n+1}, v*, a_{n+1} and its mass, and the model's changes to them are kept. Every rank
  // of a partitioned run calls it at the same point (the replicated model decides alike).
  virtual void make_current() = 0;
};

}  // namespace ccm
