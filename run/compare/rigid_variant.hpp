// The scene with some of its bodies made rigid: the second of the two runs of `ccm compare`
// (docs/compare.md). Each named body keeps its mesh, its material's density (so its mass, centre
// and inertia are those of its meshed volume), and its initial velocity. A body that [[fixed]]
// tables hold (those naming it with `body`) becomes motion = "fixed" and those tables go: its
// motion holds it now. Anything else that cannot apply to a rigid body (a load on a fixed one,
// a joint on its nodes, the sphere's penalty on its surface) is refused later by the scene
// builder, with the scene file, line and key.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "run/scene/scene.hpp"

namespace ccm {

// A name that is not a body of the scene, is given twice, or names a body already rigid.
struct RigidVariantError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

Scene with_rigid_bodies(const Scene& scene, const std::vector<std::string>& names);

}  // namespace ccm
