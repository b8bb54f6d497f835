#include "engine/contact/dcr/ccd_prefilter.hpp"

#include <algorithm>
#include <cmath>

namespace ccm::dcr {
namespace {

// The prefilter's margin, a fraction of the two edges' lengths (header).
constexpr double kSlack = 1e-5;

// Clamp to [0, 1].
double unit_clamp(double s) { return std::clamp(s, 0.0, 1.0); }

}  // namespace

// Closest points of two segments (Ericson, Real-Time Collision Detection, 5.1.9): minimise
// |c + t e2 - a - s e1| over s, t in [0, 1], clamping one parameter and re-solving the other.
double segment_distance(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 e1 = b - a, e2 = d - c, r = a - c;
  const double A = e1.squaredNorm(), E = e2.squaredNorm(), f = e2.dot(r);
  double s = 0.0, t = 0.0;
  if (A <= 0.0 && E <= 0.0) return r.norm();
  if (A <= 0.0) {
    t = unit_clamp(f / E);
  } else {
    const double cc = e1.dot(r);
    if (E <= 0.0) {
      s = unit_clamp(-cc / A);
    } else {
      const double B = e1.dot(e2), denom = A * E - B * B;
      s = denom > 0.0 ? unit_clamp((B * f - cc * E) / denom) : 0.0;
      t = (B * s + f) / E;
      if (t < 0.0) {
        t = 0.0;
        s = unit_clamp(-cc / A);
      } else if (t > 1.0) {
        t = 1.0;
        s = unit_clamp((B - cc) / A);
      }
    }
  }
  return ((a + s * e1) - (c + t * e2)).norm();
}

bool edges_may_cross(const Vec3& a0, const Vec3& b0, const Vec3& c0, const Vec3& d0, const Vec3& a1,
                     const Vec3& b1, const Vec3& c1, const Vec3& d1) {
  const double reach_ab = std::max((a1 - a0).norm(), (b1 - b0).norm());
  const double reach_cd = std::max((c1 - c0).norm(), (d1 - d0).norm());
  const double slack = kSlack * ((b0 - a0).norm() + (d0 - c0).norm());
  return !(segment_distance(a0, b0, c0, d0) > reach_ab + reach_cd + slack);
}

}  // namespace ccm::dcr
