// A pin joint's history columns (engine/bc/pin_joint.hpp): <name>.angle, its rotation about the
// axis since t = 0 [rad], and <name>.angular_velocity [rad/s], the ring's, as the joint last set
// them (a bench test's goniometer or IMU compares with these: docs/bench-test.md). A track's
// friction (engine/bc/track_friction.hpp): <name>.force, its force along the track at the last
// step [N] (negative: resisting), and <name>.sticking (1 or 0).
#pragma once

#include <string>
#include <vector>

#include "engine/bc/pin_joint.hpp"
#include "engine/bc/track_friction.hpp"
#include "engine/observe/history.hpp"

namespace ccm {

class PinJointHistory : public HistorySource {
 public:
  // Not owned: `joint` outlives the run.
  PinJointHistory(std::string name, const PinJoint& joint)
      : name_(std::move(name)), joint_(&joint) {}

  std::vector<std::string> history_columns() const override {
    return {name_ + ".angle", name_ + ".angular_velocity"};
  }
  void append_history(const State&, std::vector<double>& row) const override {
    row.push_back(joint_->angle());
    row.push_back(joint_->rate());
  }

 private:
  std::string name_;
  const PinJoint* joint_;
};

class TrackFrictionHistory : public HistorySource {
 public:
  // Not owned: `track` outlives the run.
  TrackFrictionHistory(std::string name, const TrackFriction& track)
      : name_(std::move(name)), track_(&track) {}

  std::vector<std::string> history_columns() const override {
    return {name_ + ".force", name_ + ".sticking"};
  }
  void append_history(const State&, std::vector<double>& row) const override {
    row.push_back(track_->force());
    row.push_back(track_->sticking() ? 1.0 : 0.0);
  }

 private:
  std::string name_;
  const TrackFriction* track_;
};

}  // namespace ccm
