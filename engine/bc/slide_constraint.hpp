// Nodes that may move only along one direction through their reference position: the
// Dirichlet constraints that keep the impactor on its track (thesis 3.3.2, Fig. 3-18: "restrict
// motion in the out-of-plane direction ... to maintain a single degree-of-freedom motion").
//   x = X + ((x - X) . d) d,   v* = (v* . d) d,   a = (a . d) d
// The removed components never build up (every step starts on the line), so the reactions do
// no work.
#pragma once

#include <string>
#include <vector>

#include "engine/bc/kinematic_constraint.hpp"

namespace ccm {

class SlideConstraint : public KinematicConstraint {
 public:
  // Throws std::invalid_argument when there is no node or the direction is zero or not finite.
  SlideConstraint(std::vector<int> nodes, const Vec3& direction);

  std::string_view name() const override { return "slide"; }
  void initialise(State& s) override;
  void apply(State& s, double dt) override;

  const std::vector<int>& nodes() const override { return nodes_; }
  const Vec3& direction() const { return d_; }

 private:
  void project(State& s) const;

  std::vector<int> nodes_;
  Vec3 d_;
};

}  // namespace ccm
