#include "engine/contact/dcr/ccd_prefilter.hpp"

#include <algorithm>
#include <cmath>

namespace ccm::dcr {
namespace {

// The prefilter's margin, a fraction of the edges' lengths (header).
constexpr double kSlack = kPrefilterSlack;

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

double edge_pair_slack(const Vec3& a0, const Vec3& b0, const Vec3& c0, const Vec3& d0) {
  return kSlack * ((b0 - a0).norm() + (d0 - c0).norm());
}

double face_slack(const Vec3& a0, const Vec3& b0, const Vec3& c0) {
  return kSlack * ((b0 - a0).norm() + (c0 - b0).norm() + (a0 - c0).norm());
}

bool edges_may_cross_from(double distance, const Vec3& a0, const Vec3& b0, const Vec3& c0,
                          const Vec3& d0, const Vec3& a1, const Vec3& b1, const Vec3& c1,
                          const Vec3& d1) {
  const double reach_ab = std::max((a1 - a0).norm(), (b1 - b0).norm());
  const double reach_cd = std::max((c1 - c0).norm(), (d1 - d0).norm());
  return !(distance > reach_ab + reach_cd + edge_pair_slack(a0, b0, c0, d0));
}

namespace {

// (U x V) . W stays away from 0 over the step, U moving from u0 to u1, etc. (see the header).
bool triple_stays_off_zero(const Vec3& u0, const Vec3& u1, const Vec3& v0, const Vec3& v1,
                           const Vec3& w0, const Vec3& w1) {
  const double nu = u0.norm(), nv = v0.norm(), nw = w0.norm();
  const double reach = (nu + (u1 - u0).norm()) * (nv + (v1 - v0).norm()) * (nw + (w1 - w0).norm());
  constexpr double kMargin = 1e-12;
  return std::abs(u0.cross(v0).dot(w0)) > (reach - nu * nv * nw) + kMargin * reach;
}

}  // namespace

bool edges_stay_off_plane(const Vec3& a0, const Vec3& b0, const Vec3& c0, const Vec3& d0,
                          const Vec3& a1, const Vec3& b1, const Vec3& c1, const Vec3& d1) {
  return triple_stays_off_zero(b0 - a0, b1 - a1, d0 - c0, d1 - c1, c0 - a0, c1 - a1);
}

bool node_stays_off_face_plane(const Vec3& p0, const Vec3& a0, const Vec3& b0, const Vec3& c0,
                               const Vec3& p1, const Vec3& a1, const Vec3& b1, const Vec3& c1) {
  return triple_stays_off_zero(b0 - a0, b1 - a1, c0 - a0, c1 - a1, p0 - a0, p1 - a1);
}

bool edges_may_cross(const Vec3& a0, const Vec3& b0, const Vec3& c0, const Vec3& d0, const Vec3& a1,
                     const Vec3& b1, const Vec3& c1, const Vec3& d1) {
  return edges_may_cross_from(segment_distance(a0, b0, c0, d0), a0, b0, c0, d0, a1, b1, c1, d1);
}

// Ericson, Real-Time Collision Detection, 5.1.5: the Voronoi regions of the triangle's vertices,
// edges and face, in that order.
double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return ap.norm();
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return bp.norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double v = d1 / (d1 - d3);
    return (p - (a + v * ab)).norm();
  }
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return cp.norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double w = d2 / (d2 - d6);
    return (p - (a + w * ac)).norm();
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return (p - (b + w * (c - b))).norm();
  }
  const double denom = va + vb + vc;
  if (!(denom > 0.0)) {  // degenerate triangle: the nearest of its three edges
    return std::min(
        {segment_distance(p, p, a, b), segment_distance(p, p, b, c), segment_distance(p, p, c, a)});
  }
  const double v = vb / denom, w = vc / denom;
  return (p - (a + v * ab + w * ac)).norm();
}

double node_face_reach(const Vec3& p0, const Vec3& a0, const Vec3& b0, const Vec3& c0,
                       const Vec3& p1, const Vec3& a1, const Vec3& b1, const Vec3& c1) {
  const double reach_p = (p1 - p0).norm();
  const double reach_f = std::max({(a1 - a0).norm(), (b1 - b0).norm(), (c1 - c0).norm()});
  return reach_p + reach_f;
}

bool node_face_may_touch_within(double distance, double reach, double slack, double proximity) {
  return !(distance > reach + proximity + slack);
}

bool node_face_may_touch(const Vec3& p0, const Vec3& a0, const Vec3& b0, const Vec3& c0,
                         const Vec3& p1, const Vec3& a1, const Vec3& b1, const Vec3& c1,
                         double proximity) {
  return node_face_may_touch_within(point_triangle_distance(p0, a0, b0, c0),
                                    node_face_reach(p0, a0, b0, c0, p1, a1, b1, c1),
                                    face_slack(a0, b0, c0), proximity);
}

}  // namespace ccm::dcr
