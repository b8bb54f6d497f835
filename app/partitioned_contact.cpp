#include "app/partitioned_contact.hpp"

namespace ccm {

distributed::PartitionedContact partitioned_contact(const Scene& scene, const Model& model) {
  distributed::PartitionedContact c;
  const ContactSpec& spec = scene.contact;
  c.phases.adds_forces = spec.kind == ContactKind::rigid_penalty;
  c.phases.corrects = spec.kind == ContactKind::dcr;
  // A body-pair restitution e < 1 changes the rigid motion of whole bodies.
  const bool whole_bodies = spec.kind == ContactKind::dcr && spec.restitution < 1.0;
  if (spec.kind != ContactKind::none)
    c.region = distributed::contact_region(model.mesh, whole_bodies);
  return c;
}

}  // namespace ccm
