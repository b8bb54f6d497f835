#include "engine/body/rigid_body.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ccm {
namespace {

// The fixed-point iteration of RB.5 stops when an iterate moves Pi by no more than a few units
// in the last place, or after this many iterations (it contracts by about h |w| per iteration).
constexpr int kMaxMidpointIterations = 60;
constexpr double kMidpointTolerance = 4.0 * std::numeric_limits<double>::epsilon();

}  // namespace

Quat cayley_rotation(const Vec3& v) {
  const Vec3 g = 0.5 * v;
  return Quat(1.0, g.x(), g.y(), g.z()).normalized();
}

RigidBody::RigidBody(const MassProperties& p) : mass_(p.mass), c0_(p.center), c_(p.center) {
  if (!(p.mass > 0.0)) throw std::invalid_argument("rigid body: the mass must be positive");
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(p.inertia);
  moments_ = eig.eigenvalues();
  if (!(moments_.minCoeff() > 0.0))
    throw std::invalid_argument("rigid body: a principal moment of inertia is not positive");
  Mat3 frame = eig.eigenvectors();
  if (frame.determinant() < 0.0) frame.col(2) = -frame.col(2);  // a rotation, not a reflection
  q0_ = Quat(frame).normalized();
  q_ = q0_;
}

Mat3 RigidBody::inertia_world() const {
  const Mat3 R = q_.toRotationMatrix();
  return R * moments_.asDiagonal() * R.transpose();
}

Vec3 RigidBody::angular_velocity() const {
  const Vec3 pi = q_.conjugate() * L_;
  return q_ * pi.cwiseQuotient(moments_);
}

double RigidBody::kinetic_energy() const {
  const Vec3 pi = q_.conjugate() * L_;
  return 0.5 * P_.squaredNorm() / mass_ + 0.5 * pi.dot(pi.cwiseQuotient(moments_));
}

void RigidBody::set_angular_velocity(const Vec3& w) {
  const Vec3 w_body = q_.conjugate() * w;
  L_ = q_ * moments_.cwiseProduct(w_body);
}

void RigidBody::set_pose(const Vec3& center, const Quat& rotation) {
  c_ = center;
  q_ = (rotation * q0_).normalized();
}

void RigidBody::kick(const Vec3& force, const Vec3& torque, double h) {
  P_ += h * force;
  L_ += h * torque;
}

// Rotates v by the Cayley rotation of Gibbs vector g (rotation by 2 atan|g| about g) or, with
// sign -1, by its transpose: ((1 - |g|^2) v + 2 (g . v) g + sign 2 g x v) / (1 + |g|^2).
Vec3 gibbs_rotate(const Vec3& g, const Vec3& v, double sign) {
  const double g2 = g.squaredNorm();
  return ((1.0 - g2) * v + (2.0 * g.dot(v)) * g + (2.0 * sign) * g.cross(v)) / (1.0 + g2);
}

bool RigidBody::drift(double h) {
  c_ += (h / mass_) * P_;
  const Vec3 pi0 = q_.conjugate() * L_;
  const double scale = pi0.norm();
  if (scale == 0.0) return true;
  Vec3 pi1 = pi0, g = Vec3::Zero();
  bool converged = false;
  for (int k = 0; k < kMaxMidpointIterations && !converged; ++k) {
    g = (0.25 * h) * (pi0 + pi1).cwiseQuotient(moments_);  // h w / 2, w = I^-1 (Pi_0 + Pi_1) / 2
    const Vec3 next = gibbs_rotate(g, pi0, -1.0);          // cay(h w)^T Pi_0
    converged = (next - pi1).norm() <= kMidpointTolerance * scale;
    pi1 = next;
  }
  q_ = (q_ * Quat(1.0, g.x(), g.y(), g.z())).normalized();
  return converged;
}

}  // namespace ccm
