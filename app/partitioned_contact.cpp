#include "app/partitioned_contact.hpp"

namespace ccm {

distributed::PartitionedContact partitioned_contact(const Scene& scene, const Model& model) {
  distributed::PartitionedContact c;
  const ContactSpec& spec = scene.contact;
  c.phases.adds_forces = spec.kind == ContactKind::rigid_penalty;
  c.phases.corrects = spec.kind == ContactKind::dcr;
  if (spec.kind != ContactKind::none) c.region = distributed::contact_region(model.mesh);
  return c;
}

}  // namespace ccm
