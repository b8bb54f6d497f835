// One tolerance vocabulary for every test: relative error with an explicit floor.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace ccm::test {

// |a - b| / max(|b|, floor): the error of a against the reference b.
inline double relative_error(double a, double b, double floor = 1e-300) {
  return std::abs(a - b) / std::max(std::abs(b), floor);
}

template <typename A, typename B>
double relative_error(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b,
                      double floor = 1e-300) {
  return (a - b).norm() / std::max(b.norm(), floor);
}

}  // namespace ccm::test
