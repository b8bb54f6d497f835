// What a scene's contact model reads and writes, for its replication on every rank of a
// partitioned run (engine/distributed/replicated_contact.hpp).
#pragma once

#include "engine/distributed/distributed_run.hpp"
#include "run/scene/scene.hpp"

namespace ccm {

distributed::PartitionedContact partitioned_contact(const Scene& scene, const Model& model);

}  // namespace ccm
