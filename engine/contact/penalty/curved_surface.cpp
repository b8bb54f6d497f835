#include "engine/contact/penalty/curved_surface.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

namespace ccm {
namespace {

// Corners (3 t + k) joined into smoothing groups.
struct CornerGroups {
  explicit CornerGroups(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int root(int c) {
    while (parent[static_cast<size_t>(c)] != c)
      c = parent[static_cast<size_t>(c)] =
          parent[static_cast<size_t>(parent[static_cast<size_t>(c)])];
    return c;
  }
  void join(int a, int b) { parent[static_cast<size_t>(root(a))] = root(b); }
  std::vector<int> parent;
};

// A face's weight in its corner's normal (NG.0): sin(angle) / (|p - corner| |q - corner|).
double max_weight(const Vec3& corner, const Vec3& p, const Vec3& q) {
  const Vec3 u = p - corner, v = q - corner;
  return u.cross(v).norm() / (u.squaredNorm() * v.squaredNorm());
}

// NG.2 for the edge from a (normal na) to b (normal nb). Zero where the normals agree to 1e-12
// (a straight edge) or are opposite.
Vec3 edge_coefficient(const Vec3& a, const Vec3& b, const Vec3& na, const Vec3& nb) {
  const Vec3 v = 0.5 * (na + nb), dv = 0.5 * (na - nb), e = b - a;
  const double d = e.dot(v), dd = e.dot(dv), dc = na.dot(dv);
  if (dc < 1e-12 || 1.0 - dc < 1e-12) return Vec3::Zero();
  return dd / (1.0 - dc) * v + d / dc * dv;
}

// NG.1 and its derivatives along b_1 and b_2 (b_0 = 1 - b_1 - b_2).
using Patch = CurvedSurface::PatchPoint;
Patch patch(const std::array<Vec3, 3>& v, const std::array<Vec3, 3>& c, double b1, double b2) {
  const double b0 = 1.0 - b1 - b2;
  return {
      b0 * v[0] + b1 * v[1] + b2 * v[2] - c[0] * (b0 * b1) - c[1] * (b1 * b2) - c[2] * (b2 * b0),
      v[1] - v[0] - c[0] * (b0 - b1) - c[1] * b2 + c[2] * b2,
      v[2] - v[0] + c[0] * b1 - c[1] * b1 - c[2] * (b0 - b2)};
}

constexpr int kFootIterations = 3;
constexpr int kWalks = 4;         // triangles a foot point may move across (NG.5)
constexpr double kInside = 1e-9;  // a weight this far below 0 still counts as inside

}  // namespace

CurvedSurface::CurvedSurface(const std::vector<Vec3>& vertices,
                             const std::vector<Triangle>& triangles, double crease_degrees)
    : vertices_(vertices), triangles_(triangles) {
  const size_t n = triangles_.size();
  auto vertex = [&](size_t t, int k) -> const Vec3& {
    return vertices_[static_cast<size_t>(triangles_[t][static_cast<size_t>(k)])];
  };
  for (size_t t = 0; t < n; ++t)
    face_normal_.push_back(
        (vertex(t, 1) - vertex(t, 0)).cross(vertex(t, 2) - vertex(t, 0)).normalized());
  // Each edge's two triangles; their corners at the edge's ends are joined unless it is a crease.
  std::map<std::pair<int, int>, std::vector<int>> edges;
  for (size_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) {
      const int i = triangles_[t][static_cast<size_t>(k)],
                j = triangles_[t][static_cast<size_t>((k + 1) % 3)];
      edges[{std::min(i, j), std::max(i, j)}].push_back(static_cast<int>(t));
    }
  auto corner = [&](int t, int v) {
    for (int k = 0; k < 3; ++k)
      if (triangles_[static_cast<size_t>(t)][static_cast<size_t>(k)] == v) return 3 * t + k;
    throw std::logic_error("curved surface: a vertex not on its triangle");
  };
  neighbour_.assign(n, {-1, -1, -1});
  for (const auto& [edge, sides] : edges)
    if (sides.size() == 2)
      for (int side = 0; side < 2; ++side) {
        const auto t = static_cast<size_t>(sides[static_cast<size_t>(side)]);
        for (int k = 0; k < 3; ++k) {
          const int i = triangles_[t][static_cast<size_t>(k)],
                    j = triangles_[t][static_cast<size_t>((k + 1) % 3)];
          if (std::min(i, j) == edge.first && std::max(i, j) == edge.second)
            neighbour_[t][static_cast<size_t>(k)] = sides[static_cast<size_t>(1 - side)];
        }
      }
  const double cos_crease = std::cos(crease_degrees * M_PI / 180.0);
  CornerGroups groups(3 * n);
  for (const auto& [edge, sides] : edges) {
    if (sides.size() != 2)
      throw std::invalid_argument("curved surface: an edge belongs to " +
                                  std::to_string(sides.size()) + " triangles");
    const int t1 = sides[0], t2 = sides[1];
    if (crease_degrees <= 0.0 || face_normal_[static_cast<size_t>(t1)].dot(
                                     face_normal_[static_cast<size_t>(t2)]) < cos_crease)
      continue;
    for (int v : {edge.first, edge.second}) groups.join(corner(t1, v), corner(t2, v));
  }
  // Corner normals: sums of face normals per group with Max's weights (NG.0).
  std::vector<Vec3> sum(3 * n, Vec3::Zero());
  for (size_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k)
      sum[static_cast<size_t>(groups.root(static_cast<int>(3 * t) + k))] +=
          max_weight(vertex(t, k), vertex(t, (k + 1) % 3), vertex(t, (k + 2) % 3)) *
          face_normal_[t];
  edge_c_.resize(n);
  flat_.assign(n, 1);
  allowance_.assign(n, 0.0);
  for (size_t t = 0; t < n; ++t) {
    std::array<Vec3, 3> normal;
    for (int k = 0; k < 3; ++k)
      normal[static_cast<size_t>(k)] =
          sum[static_cast<size_t>(groups.root(static_cast<int>(3 * t) + k))].normalized();
    double largest = 0.0;
    for (int k = 0; k < 3; ++k) {
      const int l = (k + 1) % 3;
      Vec3& c = edge_c_[t][static_cast<size_t>(k)];
      c = edge_coefficient(vertex(t, k), vertex(t, l), normal[static_cast<size_t>(k)],
                           normal[static_cast<size_t>(l)]);
      largest = std::max(largest, c.norm());
    }
    flat_[t] = largest == 0.0 ? 1 : 0;
    allowance_[t] = largest / 3.0;  // NG.4
    if (!flat_[t]) all_flat_ = false;
  }
}

// Gauss-Newton for the foot point of x on triangle t's patch from weights (b1, b2) (NG.3).
void CurvedSurface::foot(size_t t, const Vec3& x, double& b1, double& b2, PatchPoint& P) const {
  const std::array<Vec3, 3> v = corners(t);
  P = patch(v, edge_c_[t], b1, b2);
  for (int it = 0; it < kFootIterations; ++it) {
    const Vec3 r = x - P.x;
    const double a11 = P.t1.dot(P.t1), a12 = P.t1.dot(P.t2), a22 = P.t2.dot(P.t2);
    const double r1 = P.t1.dot(r), r2 = P.t2.dot(r), det = a11 * a22 - a12 * a12;
    if (!(det > 0.0)) break;
    b1 += (a22 * r1 - a12 * r2) / det;
    b2 += (a11 * r2 - a12 * r1) / det;
    P = patch(v, edge_c_[t], b1, b2);
  }
}

std::array<Vec3, 3> CurvedSurface::corners(size_t t) const {
  return {vertices_[static_cast<size_t>(triangles_[t][0])],
          vertices_[static_cast<size_t>(triangles_[t][1])],
          vertices_[static_cast<size_t>(triangles_[t][2])]};
}

// x's projection onto facet t's plane as barycentric weights, clamped into the triangle and
// renormalised.
std::array<double, 3> CurvedSurface::projected_inside(size_t t, const Vec3& x) const {
  const std::array<Vec3, 3> v = corners(t);
  const Vec3 e1 = v[1] - v[0], e2 = v[2] - v[0], w = x - v[0];
  const double d00 = e1.dot(e1), d01 = e1.dot(e2), d11 = e2.dot(e2), d20 = w.dot(e1),
               d21 = w.dot(e2);
  const double inverse = 1.0 / (d00 * d11 - d01 * d01);
  std::array<double, 3> b = {0.0, (d11 * d20 - d01 * d21) * inverse,
                             (d00 * d21 - d01 * d20) * inverse};
  b[0] = 1.0 - b[1] - b[2];
  double sum = 0.0;
  for (double& bi : b) sum += (bi = std::max(bi, 0.0));
  for (double& bi : b) bi /= sum;
  return b;
}

void CurvedSurface::evaluate(const Vec3& x, const SurfacePoint& flat_hit, SurfacePoint& hit,
                             std::array<double, 2>* foot_weights) const {
  const auto t = static_cast<size_t>(flat_hit.triangle);
  if (flat_[t] ||
      walk(x, t, flat_hit.weights[1], flat_hit.weights[2], hit, foot_weights) == Foot::folded)
    hit = flat_hit;
}

bool CurvedSurface::track(const Vec3& x, int triangle, std::array<double, 2> from,
                          SurfacePoint& hit, std::array<double, 2>& foot_weights) const {
  const auto t = static_cast<size_t>(triangle);
  return !flat_[t] && walk(x, t, from[0], from[1], hit, &foot_weights) == Foot::on_patch &&
         !flat_[static_cast<size_t>(hit.triangle)];
}

// The foot point (NG.3) from weights (b1, b2) of triangle t; a foot beyond an edge moves to the
// triangle across it, starting from x's projection onto that facet held inside it (NG.5), up to
// kWalks times. Fills `hit` unless the patch there is folded over its facet.
CurvedSurface::Foot CurvedSurface::walk(const Vec3& x, size_t t, double b1, double b2,
                                        SurfacePoint& hit,
                                        std::array<double, 2>* foot_weights) const {
  PatchPoint P;
  foot(t, x, b1, b2, P);
  bool inside = false;
  for (int walk = 0;; ++walk) {
    const std::array<double, 3> b = {1.0 - b1 - b2, b1, b2};
    const auto lowest = static_cast<size_t>(std::min_element(b.begin(), b.end()) - b.begin());
    inside = b[lowest] >= -kInside;
    if (inside || walk == kWalks) break;
    const int across = neighbour_[t][(lowest + 1) % 3];  // the edge opposite the lowest weight
    if (across < 0) break;
    t = static_cast<size_t>(across);
    const std::array<double, 3> w = projected_inside(t, x);
    b1 = w[1];
    b2 = w[2];
    foot(t, x, b1, b2, P);
  }
  const std::array<Vec3, 3> v = corners(t);
  const Vec3 n = P.t1.cross(P.t2).normalized();
  const Vec3& nf = face_normal_[t];
  if (!(n.dot(nf) > 0.0)) return Foot::folded;
  // Where the line x + tau n meets the facet's plane, and its barycentric weights.
  const Vec3 q = x + (v[0] - x).dot(nf) / n.dot(nf) * n;
  const Vec3 e1 = v[1] - v[0], e2 = v[2] - v[0], w = q - v[0];
  const double d00 = e1.dot(e1), d01 = e1.dot(e2), d11 = e2.dot(e2), d20 = w.dot(e1),
               d21 = w.dot(e2);
  const double inverse = 1.0 / (d00 * d11 - d01 * d01);
  const double w1 = (d11 * d20 - d01 * d21) * inverse, w2 = (d00 * d21 - d01 * d20) * inverse;
  hit.depth = (P.x - x).dot(n);
  hit.point = q;
  hit.normal = n;
  hit.triangle = static_cast<int>(t);
  hit.weights = {1.0 - w1 - w2, w1, w2};
  if (foot_weights) *foot_weights = {b1, b2};
  return inside ? Foot::on_patch : Foot::off_patch;
}

}  // namespace ccm
