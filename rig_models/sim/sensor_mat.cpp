#include "rig_models/sim/sensor_mat.hpp"

#include <cmath>
#include <stdexcept>

#include "engine/core/unit_direction.hpp"

namespace ccm::rig {

SensorMat::SensorMat(const ModelMesh& mesh, const std::vector<Triangle>& tip,
                     const std::vector<Triangle>& footprint, const Vec3& track, SensorMatLaw law)
    : tip_(area_shares(tip, mesh.X)), mat_(area_shares(footprint, mesh.X)), law_(law) {
  if (!(tip_.area > 0.0) || !(mat_.area > 0.0))
    throw std::invalid_argument("sensor mat: the tip's face or the mat's footprint has no area");
  d_ = unit_direction(track, "sensor mat: the track direction");
  if (!(law_.stiffness > 0.0) || !std::isfinite(law_.stiffness) || !(law_.exponent >= 0.0) ||
      !std::isfinite(law_.exponent) || !(law_.damping >= 0.0) || !std::isfinite(law_.damping))
    throw std::invalid_argument(
        "sensor mat: the stiffness must be > 0, the exponent and damping >= 0, all finite");
  gap0_ = along(mat_, mesh.X) - along(tip_, mesh.X);
}

double SensorMat::along(const AreaShares& face, const std::vector<Vec3>& x) const {
  double u = 0.0;
  for (size_t j = 0; j < face.nodes.size(); ++j)
    u += face.share[j] * x[static_cast<size_t>(face.nodes[j])].dot(d_);
  return u;
}

void SensorMat::add_forces(const State& s, std::span<Vec3> f) {
  const double delta = along(tip_, s.x) - along(mat_, s.x) + gap0_;
  const double rate = along(tip_, s.v) - along(mat_, s.v);
  // (SM.1)
  const double F = delta > 0.0 ? std::max(0.0, law_.stiffness * std::pow(delta, law_.exponent) *
                                                   (1.0 + law_.damping * rate))
                               : 0.0;
  for (size_t j = 0; j < tip_.nodes.size(); ++j)
    f[static_cast<size_t>(tip_.nodes[j])] -= tip_.share[j] * F * d_;
  for (size_t j = 0; j < mat_.nodes.size(); ++j)
    f[static_cast<size_t>(mat_.nodes[j])] += mat_.share[j] * F * d_;
  // Work on the bodies: -F d(delta), trapezoidal in time (both faces move; F is internal).
  work_ -= 0.5 * (F_ + F) * (std::max(delta, 0.0) - std::max(delta_, 0.0));
  F_ = F;
  delta_ = delta;
}

void SensorMat::end_step(const State& /*s*/, double dt) {
  impulse_ += F_ * dt;
  time_ += dt;
}

double SensorMat::mean_force_since_last() {
  const double mean = time_ > 0.0 ? impulse_ / time_ : 0.0;
  impulse_ = time_ = 0.0;
  return mean;
}

}  // namespace ccm::rig
