#include "engine/contact/dcr/ccd.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace ccm::dcr {
namespace {

constexpr double kRoundoff = std::numeric_limits<double>::epsilon() / 2;  // u
constexpr double kNoiseFactor = 64;        // |6 g| <= 64 u L_U L_V L_W is "zero" (see ccd.hpp)
constexpr double kDegenerateSine = 1e-12;  // triangle: |B x C| below this times |B| |C|
constexpr double kParallelSine = 1e-8;     // edges: |e1 x e2| below this times |e1| |e2|
constexpr double kWindowSlack = 1e-10;     // extra barycentric tolerance inside a window
constexpr double kTimeResolution = 1e-17;  // roots are not refined below this (in step units)

// A vector moving linearly over the step: X(tau) = (1 - tau) X0 + tau X1 (exact at both ends).
struct Moving {
  Vec3 x0, x1;
  Vec3 at(double tau) const { return (1 - tau) * x0 + tau * x1; }
  Vec3 rate() const { return x1 - x0; }
  double max_norm() const { return std::max(x0.norm(), x1.norm()); }
};

// (U x V) . W at tau, evaluated from the positions (not from expanded coefficients).
double triple(const Moving& u, const Moving& v, const Moving& w, double tau) {
  return u.at(tau).cross(v.at(tau)).dot(w.at(tau));
}

// Coefficients k0..k3 of (U x V) . W as a cubic in tau (used for its critical points only).
std::array<double, 4> triple_cubic(const Moving& u, const Moving& v, const Moving& w) {
  const Vec3 du = u.rate(), dv = v.rate(), dw = w.rate();
  const Vec3 n0 = u.x0.cross(v.x0);
  const Vec3 n1 = u.x0.cross(dv) + du.cross(v.x0);
  const Vec3 n2 = du.cross(dv);
  return {n0.dot(w.x0), n0.dot(dw) + n1.dot(w.x0), n1.dot(dw) + n2.dot(w.x0), n2.dot(dw)};
}

// Coefficients c0..c2 of (X x Y) . n as a quadratic in tau, n fixed.
std::array<double, 3> cross_dot_quadratic(const Moving& x, const Moving& y, const Vec3& n) {
  const Vec3 dx = x.rate(), dy = y.rate();
  return {x.x0.cross(y.x0).dot(n), (x.x0.cross(dy) + dx.cross(y.x0)).dot(n), dx.cross(dy).dot(n)};
}

double horner(const std::array<double, 3>& c, double t) { return c[0] + t * (c[1] + t * c[2]); }

// A few times in ascending order, on the stack.
struct Times {
  std::array<double, 64> v{};
  int n = 0;
  void push(double t) {
    if (n < static_cast<int>(v.size())) v[static_cast<size_t>(n++)] = t;
  }
  void sort() { std::sort(v.begin(), v.begin() + n); }
  double operator[](int i) const { return v[static_cast<size_t>(i)]; }
};

// Narrows [l, r], where h(l) = hl and h(r) = hr have opposite signs (neither zero), around the
// root of h until the bracket is a few ulps wide: false position with the Illinois modification
// (superlinear), and a bisection step whenever two steps did not halve the bracket. Returns the
// final bracket (a single point when h is exactly zero there).
template <typename H>
std::pair<double, double> bracket_root(H&& h, double l, double r, double hl, double hr) {
  double width_before = 2 * (r - l), width_now = r - l;  // the first step is false position
  int side = 0;
  for (int it = 0; it < 200; ++it) {
    const double m = 0.5 * (l + r);
    if (!(m > l && m < r) || r - l <= 4 * kRoundoff * std::max(std::abs(l), std::abs(r)) ||
        r - l <= kTimeResolution)
      break;
    double c = (hl * r - hr * l) / (hl - hr);
    if (!(c > l && c < r) || (it % 2 == 0 && width_now > 0.5 * width_before)) c = m;
    if (it % 2 == 0) width_before = width_now;
    const double hc = h(c);
    if (hc == 0) return {c, c};
    if ((hc < 0) == (hr < 0)) {
      r = c;
      hr = hc;
      if (side == -1) hl *= 0.5;
      side = -1;
    } else {
      l = c;
      hl = hc;
      if (side == 1) hr *= 0.5;
      side = 1;
    }
    width_now = r - l;
  }
  return {l, r};
}

// Roots in (a, b) of the derivative k1 + 2 k2 t + 3 k3 t^2, ascending.
int critical_points(const std::array<double, 4>& k, double a, double b, double out[2]) {
  const double qa = 3 * k[3], qb = 2 * k[2], qc = k[1];
  double r[2];
  int n = 0;
  if (qa == 0) {
    if (qb != 0) r[n++] = -qc / qb;
  } else {
    const double disc = qb * qb - 4 * qa * qc;
    if (disc >= 0) {
      const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
      r[n++] = q / qa;
      if (q != 0) r[n++] = qc / q;
    }
  }
  int m = 0;
  for (int i = 0; i < n; ++i)
    if (r[i] > a && r[i] < b) out[m++] = r[i];
  if (m == 2 && out[0] > out[1]) std::swap(out[0], out[1]);
  return m;
}

// Pushes onto `times` the points of [lo, hi] where the quadratic c may start to be >= 0: its
// sign changes (the side where it is >= 0), its zeros and its extremum.
void quadratic_entries(const std::array<double, 3>& c, double lo, double hi, Times& times) {
  double cuts[3] = {lo, hi, hi};
  int n_cuts = 2;
  if (c[2] != 0) {
    const double m = -c[1] / (2 * c[2]);
    if (m > lo && m < hi) {
      cuts[1] = m;
      cuts[2] = hi;
      n_cuts = 3;
      times.push(m);
    }
  }
  auto g = [&c](double t) { return horner(c, t); };
  for (int i = 0; i + 1 < n_cuts; ++i) {
    const double l = cuts[i], r = cuts[i + 1];
    const double gl = g(l), gr = g(r);
    if (gl == 0) times.push(l);
    if (gr == 0) times.push(r);
    if ((gl < 0 && gr > 0) || (gl > 0 && gr < 0)) {
      const auto [bl, br] = bracket_root(g, l, r, gl, gr);
      times.push(g(bl) >= 0 ? bl : br);
    }
  }
}

// The inclusion conditions of one pair type at a fixed normal n: w_i = alpha_i / D must lie in
// [-tol, 1 + tol] for i < n_alpha, with alpha_i and D quadratics in tau.
struct Conditions {
  std::array<std::array<double, 3>, 3> alpha;
  std::array<double, 3> denominator;
  int n_alpha;
};

// The first tau in [lo, hi] at which all conditions hold (with kWindowSlack), or -1. The set
// where they hold starts at lo or at a zero of one of the quadratics alpha + tol D or
// (1 + tol) D - alpha, so only those times are tested. `weights` receives alpha_i / D there.
double first_inclusion(const Conditions& c, double lo, double hi, double tol,
                       double min_denominator, std::array<double, 3>& weights) {
  Times times;
  times.push(lo);
  for (int i = 0; i < c.n_alpha; ++i) {
    std::array<double, 3> low, high;
    for (size_t j = 0; j < 3; ++j) {
      low[j] = c.alpha[static_cast<size_t>(i)][j] + tol * c.denominator[j];
      high[j] = (1 + tol) * c.denominator[j] - c.alpha[static_cast<size_t>(i)][j];
    }
    quadratic_entries(low, lo, hi, times);
    quadratic_entries(high, lo, hi, times);
  }
  times.sort();
  const double lower = -tol - kWindowSlack, upper = 1 + tol + kWindowSlack;
  for (int k = 0; k < times.n; ++k) {
    const double t = times[k];
    const double d = horner(c.denominator, t);
    if (!(d > min_denominator)) continue;
    bool inside = true;
    for (int i = 0; i < c.n_alpha && inside; ++i) {
      const double w = horner(c.alpha[static_cast<size_t>(i)], t) / d;
      weights[static_cast<size_t>(i)] = w;
      inside = w >= lower && w <= upper;
    }
    if (inside) return t;
  }
  return -1;
}

// Shared driver. The pair is coplanar where (U x V) . W = 0; `at_root(tau, out)` tests inclusion
// at one time (fresh normal), `window(lo, hi, out)` the first inclusion over a window (frozen
// normal). Returns the time of impact or -1.
template <typename AtRoot, typename Window>
double first_hit(const Moving& u, const Moving& v, const Moving& w, AtRoot&& at_root,
                 Window&& window) {
  const double eps = kNoiseFactor * kRoundoff * u.max_norm() * v.max_norm() * w.max_norm();
  auto f = [&](double t) { return triple(u, v, w, t); };

  // Monotone pieces of f on [0, 1].
  double cuts[4] = {0, 1, 1, 1};
  double crit[2];
  const std::array<double, 4> k = triple_cubic(u, v, w);
  const int n_crit = critical_points(k, 0, 1, crit);
  for (int i = 0; i < n_crit; ++i) cuts[i + 1] = crit[i];
  cuts[n_crit + 1] = 1;
  double values[4];
  for (int i = 0; i < n_crit + 2; ++i) values[i] = f(cuts[i]);

  auto slope = [&k](double t) { return k[1] + t * (2 * k[2] + t * 3 * k[3]); };

  for (int piece = 0; piece <= n_crit; ++piece) {
    const double l = cuts[piece], r = cuts[piece + 1];
    const double fl = values[piece], fr = values[piece + 1];
    if ((fl > eps && fr > eps) || (fl < -eps && fr < -eps)) continue;  // no root, no window

    // A true root (sign change or exact zero): test inclusion there first.
    double root = -1;
    if (fl == 0) {
      root = l;
    } else if (fr == 0) {
      root = r;
    } else if ((fl < 0) != (fr < 0)) {
      const auto [bl, br] = bracket_root(f, l, r, fl, fr);
      root = std::abs(f(bl)) <= std::abs(f(br)) ? bl : br;
    }
    if (root >= 0 && at_root(root)) return root;

    // The window where |f| <= eps: on this monotone piece an interval [wl, wr]. Any interval
    // that contains it will do (the search over it is conservative), so around a root it is
    // found by stepping out from the root, starting at 4 eps / |f'|; elsewhere by bracketing
    // the crossings of +-eps.
    double wl = l, wr = r;
    const double step0 = root >= 0 ? 4 * eps / std::abs(slope(root)) : 0;
    if (root >= 0 && step0 > 0 && std::isfinite(step0)) {
      if (std::abs(fl) > eps) {
        wl = l;
        for (double d = step0; root - d > l; d *= 16)
          if (std::abs(f(root - d)) > eps) {
            wl = root - d;
            break;
          }
      }
      if (std::abs(fr) > eps) {
        wr = r;
        for (double d = step0; root + d < r; d *= 16)
          if (std::abs(f(root + d)) > eps) {
            wr = root + d;
            break;
          }
      }
    } else {
      if (std::abs(fl) > eps) {
        const double level = fl > eps ? eps : -eps;
        auto h = [&](double t) { return f(t) - level; };
        wl = bracket_root(h, l, r, fl - level, fr - level).second;
      }
      if (std::abs(fr) > eps) {
        const double level = fr > eps ? eps : -eps;
        auto h = [&](double t) { return f(t) - level; };
        const double hl = f(wl) - level;
        wr = hl == 0 ? wl : bracket_root(h, wl, r, hl, fr - level).first;
      }
    }
    if (wl > wr) std::swap(wl, wr);
    const double t = window(wl, wr);
    if (t >= 0) return t;
  }
  return -1;
}

}  // namespace

std::optional<NodeFaceHit> node_face_ccd(const Vec3& p0, const Vec3& a0, const Vec3& b0,
                                         const Vec3& c0, const Vec3& p1, const Vec3& a1,
                                         const Vec3& b1, const Vec3& c1, double tol) {
  const Moving B{b0 - a0, b1 - a1}, C{c0 - a0, c1 - a1}, P{p0 - a0, p1 - a1};
  NodeFaceHit hit{};

  // Barycentric weights of the projection of P on the plane of (0, B, C) at tau.
  auto at_root = [&](double tau) {
    const Vec3 b = B.at(tau), c = C.at(tau), p = P.at(tau);
    const Vec3 n = b.cross(c);
    const double d = n.squaredNorm();
    if (!(d > kDegenerateSine * kDegenerateSine * b.squaredNorm() * c.squaredNorm())) return false;
    const double wb = p.cross(c).dot(n) / d, wc = b.cross(p).dot(n) / d, wa = 1 - wb - wc;
    if (wa < -tol || wa > 1 + tol || wb < -tol || wb > 1 + tol || wc < -tol || wc > 1 + tol)
      return false;
    hit = {tau, wa, wb, wc};
    return true;
  };

  auto window = [&](double lo, double hi) {
    const double mid = 0.5 * (lo + hi);
    const Vec3 n = B.at(mid).cross(C.at(mid));
    const double scale = B.max_norm() * C.max_norm();
    if (!(n.norm() > kDegenerateSine * scale)) return -1.0;
    Conditions cond;
    cond.n_alpha = 3;
    cond.denominator = cross_dot_quadratic(B, C, n);
    cond.alpha[1] = cross_dot_quadratic(P, C, n);  // w_b D
    cond.alpha[2] = cross_dot_quadratic(B, P, n);  // w_c D
    for (size_t j = 0; j < 3; ++j)
      cond.alpha[0][j] = cond.denominator[j] - cond.alpha[1][j] - cond.alpha[2][j];
    std::array<double, 3> w{};
    const double t = first_inclusion(cond, lo, hi, tol, kDegenerateSine * scale * n.norm(), w);
    if (t >= 0) hit = {t, w[0], w[1], w[2]};
    return t;
  };

  if (first_hit(B, C, P, at_root, window) < 0) return std::nullopt;
  return hit;
}

std::optional<EdgeEdgeHit> edge_edge_ccd(const Vec3& a0, const Vec3& b0, const Vec3& c0,
                                         const Vec3& d0, const Vec3& a1, const Vec3& b1,
                                         const Vec3& c1, const Vec3& d1, double tol) {
  const Moving E1{b0 - a0, b1 - a1}, E2{d0 - c0, d1 - c1}, R{c0 - a0, c1 - a1};
  EdgeEdgeHit hit{};

  // Closest-point parameters of the two lines at tau: s e1 - t e2 = r projected along e1 x e2.
  auto at_root = [&](double tau) {
    const Vec3 e1 = E1.at(tau), e2 = E2.at(tau), r = R.at(tau);
    const Vec3 n = e1.cross(e2);
    const double d = n.squaredNorm();
    if (!(d > kParallelSine * kParallelSine * e1.squaredNorm() * e2.squaredNorm())) return false;
    const double s = r.cross(e2).dot(n) / d, t = r.cross(e1).dot(n) / d;
    if (s < -tol || s > 1 + tol || t < -tol || t > 1 + tol) return false;
    hit = {tau, s, t};
    return true;
  };

  auto window = [&](double lo, double hi) {
    const double mid = 0.5 * (lo + hi);
    const Vec3 n = E1.at(mid).cross(E2.at(mid));
    const double scale = E1.max_norm() * E2.max_norm();
    if (!(n.norm() > kParallelSine * scale)) return -1.0;
    Conditions cond;
    cond.n_alpha = 2;
    cond.denominator = cross_dot_quadratic(E1, E2, n);
    cond.alpha[0] = cross_dot_quadratic(R, E2, n);  // s D
    cond.alpha[1] = cross_dot_quadratic(R, E1, n);  // t D
    std::array<double, 3> w{};
    const double t = first_inclusion(cond, lo, hi, tol, kParallelSine * scale * n.norm(), w);
    if (t >= 0) hit = {t, w[0], w[1]};
    return t;
  };

  if (first_hit(E1, E2, R, at_root, window) < 0) return std::nullopt;
  return hit;
}

double node_face_volume(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  return (b - a).cross(c - a).dot(p - a) / 6.0;
}

void node_face_volume_gradient(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c,
                               Vec3 grad[4]) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  grad[0] = ab.cross(ac) / 6.0;
  grad[2] = ac.cross(ap) / 6.0;
  grad[3] = ap.cross(ab) / 6.0;
  grad[1] = -(grad[0] + grad[2] + grad[3]);
}

double edge_edge_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).cross(d - c).dot(c - a) / 6.0;
}

void edge_edge_volume_gradient(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
                               Vec3 grad[4]) {
  const Vec3 e1 = b - a, e2 = d - c, r = c - a;
  const Vec3 n = e1.cross(e2);
  grad[0] = -(e2.cross(r) + n) / 6.0;
  grad[1] = e2.cross(r) / 6.0;
  grad[2] = (n - r.cross(e1)) / 6.0;
  grad[3] = r.cross(e1) / 6.0;
}

}  // namespace ccm::dcr
