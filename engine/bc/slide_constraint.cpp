#include "engine/bc/slide_constraint.hpp"

#include <cmath>
#include <stdexcept>

#include "engine/core/unit_direction.hpp"

namespace ccm {

SlideConstraint::SlideConstraint(std::vector<int> nodes, const Vec3& direction)
    : nodes_(std::move(nodes)) {
  if (nodes_.empty()) throw std::invalid_argument("slide constraint: no node");
  d_ = unit_direction(direction, "slide constraint: the direction");
}

void SlideConstraint::project(State& s) const {
  for (int n : nodes_) {
    const auto i = static_cast<size_t>(n);
    s.x[i] = s.X[i] + (s.x[i] - s.X[i]).dot(d_) * d_;
    s.v[i] = s.v[i].dot(d_) * d_;
    s.a[i] = s.a[i].dot(d_) * d_;
  }
}

void SlideConstraint::initialise(State& s) { project(s); }

void SlideConstraint::apply(State& s, double /*dt*/) { project(s); }

}  // namespace ccm
