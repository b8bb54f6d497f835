// The designer's metrics of a comparison (docs/metrics.md, IM.1-IM.5): the impactor's peak contact
// force, the artifact's deepest indentation, the contact duration and the rebound speed, of the
// deformable and the rigid run of a scene, and the rigid run's error in each. Read from the runs'
// histories (<impactor>.vx, vy, vz: its centre-of-mass velocity; <artifact>.u_max) on the common
// sample times, with the impactor's mass from the scene's groups (scene_groups.hpp).
#pragma once

#include <optional>
#include <string>

#include "records/point_metrics.hpp"
#include "run/compare/scene_comparison.hpp"

namespace ccm {

struct CompareImpact {
  study::ImpactQuantities deformable, rigid;
  study::ImpactErrors errors;
};

// None when either run lacks the columns or the impactor never moved.
std::optional<CompareImpact> compare_impact(const ComparedRun& deformable, const ComparedRun& rigid,
                                            const std::string& impactor,
                                            const std::string& artifact, double impactor_mass);

}  // namespace ccm
