#include "engine/body/mass_properties.hpp"

#include <cmath>
#include <stdexcept>

namespace ccm {

MassProperties tet_mass_properties(const std::vector<Tet>& tets, const std::vector<Vec3>& x,
                                   double rho) {
  if (!(rho > 0.0) || !std::isfinite(rho))
    throw std::invalid_argument("mass properties: the density must be positive");
  double volume = 0.0;
  Vec3 first = Vec3::Zero();
  Mat3 second = Mat3::Zero();  // integral of x x^T over the volume (RB.1)
  for (const Tet& t : tets) {
    const double v = six_volume(t, x) / 6.0;
    Vec3 s = Vec3::Zero();
    Mat3 outer = Mat3::Zero();
    for (int n : t) {
      const Vec3& p = x[static_cast<size_t>(n)];
      s += p;
      outer += p * p.transpose();
    }
    volume += v;
    first += v * 0.25 * s;
    second += (v / 20.0) * (outer + s * s.transpose());
  }
  if (!(volume > 0.0)) throw std::invalid_argument("mass properties: the volume is not positive");
  MassProperties p;
  p.mass = rho * volume;
  p.center = first / volume;
  const Mat3 central = rho * second - p.mass * p.center * p.center.transpose();  // RB.2
  p.inertia = central.trace() * Mat3::Identity() - central;
  return p;
}

Mat3 inertia_about(const MassProperties& p, const Vec3& d) {
  return p.inertia + p.mass * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
}

}  // namespace ccm
