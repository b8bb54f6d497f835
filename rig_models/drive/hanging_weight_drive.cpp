#include "rig_models/drive/hanging_weight_drive.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "engine/mesh/boundary_surface.hpp"

namespace ccm::rig {

HangingWeightDrive::HangingWeightDrive(const ModelMesh& mesh,
                                       const std::vector<Triangle>& drive_surface,
                                       std::vector<int> impactor_nodes, const Vec3& track,
                                       HangingWeightSettings settings)
    : nodes_(std::move(impactor_nodes)), set_(settings) {
  AreaShares shares = area_shares(drive_surface, mesh.X);
  if (!(shares.area > 0.0))
    throw std::invalid_argument("hanging weight: the drive surface has no area");
  drive_nodes_ = std::move(shares.nodes);
  drive_share_ = std::move(shares.share);
  if (nodes_.empty()) throw std::invalid_argument("hanging weight: no impactor node");
  if (!(track.norm() > 0.0)) throw std::invalid_argument("hanging weight: zero track direction");
  if (!(set_.weight_mass > 0.0) || !(set_.string_stiffness > 0.0))
    throw std::invalid_argument("hanging weight: weight mass and string stiffness must be > 0");
  d_ = track.normalized();
}

void HangingWeightDrive::first_call(const State& s) {
  double M = 0.0;
  for (int n : nodes_) M += s.m_lumped[static_cast<size_t>(n)];
  for (int n : nodes_) mass_share_.push_back(s.m_lumped[static_cast<size_t>(n)] / M);
  started_ = true;
}

void HangingWeightDrive::add_forces(const State& s, std::span<Vec3> f) {
  if (!started_) first_call(s);
  double u = 0.0, u_dot = 0.0, u_drive = 0.0;
  for (size_t j = 0; j < nodes_.size(); ++j) {
    const auto i = static_cast<size_t>(nodes_[j]);
    u += mass_share_[j] * (s.x[i] - s.X[i]).dot(d_);
    u_dot += mass_share_[j] * s.v[i].dot(d_);
  }
  for (size_t j = 0; j < drive_nodes_.size(); ++j) {
    const auto i = static_cast<size_t>(drive_nodes_[j]);
    u_drive += drive_share_[j] * (s.x[i] - s.X[i]).dot(d_);
  }
  const double k = set_.string_stiffness;
  const double e = set_.weight_mass * set_.gravity / k + s_w_ - u;
  const double T = e > 0.0 ? std::max(0.0, k * e + set_.string_damping * (w_ - u_dot)) : 0.0;
  for (size_t j = 0; j < drive_nodes_.size(); ++j)
    f[static_cast<size_t>(drive_nodes_[j])] += drive_share_[j] * T * d_;
  // Work on the impactor: trapezoidal in time, on the displacement the drive surface follows.
  work_ += 0.5 * (T_ + T) * (u_drive - u_drive_);
  T_ = T;
  u_drive_ = u_drive;
}

// The weight's own step (symplectic Euler), with the tension of this step's evaluation.
void HangingWeightDrive::end_step(const State& /*s*/, double dt) {
  w_ += dt * (set_.gravity - T_ / set_.weight_mass);
  s_w_ += dt * w_;
}

double run_up_distance(const HangingWeightSettings& s, const TrackFrictionSpec& track,
                       double impactor_mass, double speed) {
  if (!(speed > 0.0) || !(impactor_mass > 0.0))
    throw std::invalid_argument("run-up distance: speed and impactor mass must be > 0");
  const double pull = s.weight_mass * s.gravity;
  if (pull <= track.mu_s * track.normal_force)
    throw std::invalid_argument(fmt::format(
        "run-up distance: the weight's pull ({:.3g} N) cannot break the impactor away from the "
        "track's static friction ({:.3g} N)",
        pull, track.mu_s * track.normal_force));
  const double M = impactor_mass + s.weight_mass, dt = 1e-5;
  double v = 0.0, x = 0.0;
  for (double t = 0.0; t < 60.0; t += dt) {
    const double F = pull - track.mu_k * track.normal_force - track.damping * v;
    const double v_next = v + dt * F / M;
    if (v_next >= speed) return x + dt * 0.5 * (v + speed);
    if (!(v_next > v)) break;  // terminal speed below the target
    x += dt * 0.5 * (v + v_next);
    v = v_next;
  }
  throw std::invalid_argument(fmt::format(
      "run-up distance: the weight cannot bring the impactor to {} m/s against the track's "
      "friction (it levels off near {:.3g} m/s)",
      speed, v));
}

}  // namespace ccm::rig
