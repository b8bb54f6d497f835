// Our own aliases for the fixed-size Eigen types used throughout the engine.
#pragma once

#include <Eigen/Core>

namespace ccm {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

}  // namespace ccm
