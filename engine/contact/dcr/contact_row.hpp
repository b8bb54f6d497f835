// One contact of the DCR velocity solve (contact_impulses.hpp): its normal row and its two
// tangential rows on four nodes.
#pragma once

#include <array>

#include "engine/core/types.hpp"

namespace ccm::dcr {

struct ContactRow {
  std::array<int, 4> nodes{};                 // global node ids
  std::array<Vec3, 4> grad{};                 // grad g on each node (normal row)
  std::array<double, 4> beta{};               // contact-point weights for the tangential rows
  Vec3 t1 = Vec3::Zero(), t2 = Vec3::Zero();  // orthonormal tangents
  double S = 0.0;                             // normal impulse in N s per unit lambda_n
  double target = 0.0;                        // lower bound of rate_n (<= 0)
  double W_n = 0.0, W_t = 0.0;                // mobilities grad^T M^-1 grad and sum beta^2 / m
  double lambda_n = 0.0;                      // accumulated normal multiplier
  double lambda_t1 = 0.0, lambda_t2 = 0.0;    // accumulated tangential impulses [N s]
};

}  // namespace ccm::dcr
