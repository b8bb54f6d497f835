#include "engine/contact/dcr/step_limit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ccm::dcr {
namespace {

// The largest approach speed along the unit normal n (pointing from side A to side B) of a node
// of B towards a node of A: max over pairs of -(v_b - v_a) . n, >= 0.
template <size_t NA, size_t NB>
double approach_speed(const std::array<int, NA>& a, const std::array<int, NB>& b, const Vec3& n,
                      const std::vector<Vec3>& v) {
  double u = 0.0;
  for (int i : a)
    for (int j : b)
      u = std::max(u, -(v[static_cast<size_t>(j)] - v[static_cast<size_t>(i)]).dot(n));
  return u;
}

double edge_length(const std::vector<Vec3>& X, int a, int b) {
  return (X[static_cast<size_t>(b)] - X[static_cast<size_t>(a)]).norm();
}

// The largest relative speed of a node of b and a node of a: an upper bound of the approach
// speed along any normal.
template <size_t NA, size_t NB>
double relative_speed(const std::array<int, NA>& a, const std::array<int, NB>& b,
                      const std::vector<Vec3>& v) {
  double u2 = 0.0;
  for (int i : a)
    for (int j : b)
      u2 = std::max(u2, (v[static_cast<size_t>(j)] - v[static_cast<size_t>(i)]).squaredNorm());
  return std::sqrt(u2);
}

// Whether a pair of shortest edge L whose nodes move at relative speeds up to u_max can set a
// limit below `current`: its limit is at least step_fraction L / u_max (gap >= 0, u <= u_max),
// so when that is not below `current` the pair is skipped (the result is the same).
bool may_bind(double L, double u_max, double step_fraction, double current) {
  return step_fraction * L < current * u_max;
}

// dt allowed by one pair: (gap + step_fraction L) / u, infinity when u = 0.
double allowed(double gap, double L, double u, double step_fraction) {
  return u > 0.0 ? (gap + step_fraction * L) / u : std::numeric_limits<double>::infinity();
}

}  // namespace

ReferenceLengths reference_lengths(const SurfaceFeatures& f, const std::vector<Vec3>& X) {
  ReferenceLengths out;
  out.face_shortest_edge.reserve(f.faces.size());
  for (const Triangle& t : f.faces)
    out.face_shortest_edge.push_back(std::min(
        {edge_length(X, t[0], t[1]), edge_length(X, t[1], t[2]), edge_length(X, t[2], t[0])}));
  out.edge.reserve(f.edges.size());
  for (const auto& e : f.edges) out.edge.push_back(edge_length(X, e[0], e[1]));
  for (double L : out.edge) {
    out.shortest = std::min(out.shortest, L);
    out.longest = std::max(out.longest, L);
  }
  return out;
}

PairStepLimit pair_step_limit(const SurfaceFeatures& f, const Candidates& c,
                              const ReferenceLengths& lengths, const std::vector<Vec3>& x,
                              const std::vector<Vec3>& v, double step_fraction, double ceiling,
                              double fastest_node_speed) {
  PairStepLimit out{std::numeric_limits<double>::infinity(), -1};
  // Every pair allows at least step_fraction L_min / u_max, with u_max = twice the fastest node's
  // speed (a bound of every pair's relative speed; the margin 1e-12 covers the rounding of the
  // pairs' own differences): when that is not below the ceiling, no pair can shorten the step (a
  // resting contact, an impact far below the mesh's speed).
  const double u_max = 2.0 * (1.0 + 1e-12) * fastest_node_speed;
  if (!may_bind(lengths.shortest, u_max, step_fraction, ceiling)) return out;
  auto keep = [&](double dt, size_t k) {
    if (dt < out.dt) out = {dt, static_cast<int>(k)};
  };
  // A pair is evaluated only when it may set a limit below both the smallest so far and the
  // ceiling (may_bind).
  auto below = [&] { return std::min(out.dt, ceiling); };
  for (size_t k = 0; k < c.node_face.size(); ++k) {
    const int p = f.nodes[static_cast<size_t>(c.node_face[k].node)];
    const auto face = static_cast<size_t>(c.node_face[k].face);
    const Triangle& t = f.faces[face];
    const double L = lengths.face_shortest_edge[face];
    if (!may_bind(L, relative_speed(t, std::array<int, 1>{p}, v), step_fraction, below())) continue;
    const Vec3& a = x[t[0]];
    Vec3 n = (x[t[1]] - a).cross(x[t[2]] - a);
    if (!(n.norm() > 0.0)) continue;
    n.normalize();
    double d = (x[static_cast<size_t>(p)] - a).dot(n);
    if (d < 0.0) {
      n = -n;
      d = -d;
    }
    keep(allowed(d, L, approach_speed(t, std::array<int, 1>{p}, n, v), step_fraction), k);
  }
  const size_t n_nf = c.node_face.size();
  for (size_t k = 0; k < c.edge_edge.size(); ++k) {
    const auto edge_a = static_cast<size_t>(c.edge_edge[k].edge_a);
    const auto edge_b = static_cast<size_t>(c.edge_edge[k].edge_b);
    const auto& ea = f.edges[edge_a];
    const auto& eb = f.edges[edge_b];
    const double L = std::min(lengths.edge[edge_a], lengths.edge[edge_b]);
    if (!may_bind(L, relative_speed(ea, eb, v), step_fraction, below())) continue;
    const Vec3 da = x[ea[1]] - x[ea[0]], db = x[eb[1]] - x[eb[0]];
    const Vec3 between = 0.5 * (x[eb[0]] + x[eb[1]] - x[ea[0]] - x[ea[1]]);
    Vec3 n = da.cross(db);
    // Parallel edges: the normal is the direction between their midpoints.
    if (!(n.norm() > 1e-6 * da.norm() * db.norm())) n = between;
    if (!(n.norm() > 0.0)) continue;
    n.normalize();
    double d = (x[eb[0]] - x[ea[0]]).dot(n);
    if (d < 0.0) {
      n = -n;
      d = -d;
    }
    keep(allowed(d, L, approach_speed(ea, eb, n, v), step_fraction), n_nf + k);
  }
  return out;
}

}  // namespace ccm::dcr
