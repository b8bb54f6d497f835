#include "engine/contact/penalty/surface_distance.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include "engine/contact/penalty/corner_angle.hpp"

namespace ccm {
namespace {

// The point of triangle (a, b, c) closest to p, as barycentric weights (Ericson, Real-Time
// Collision Detection, 5.1.5).
std::array<double, 3> closest_weights(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {1.0, 0.0, 0.0};
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return {0.0, 1.0, 0.0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double v = d1 / (d1 - d3);
    return {1.0 - v, v, 0.0};
  }
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return {0.0, 0.0, 1.0};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double w = d2 / (d2 - d6);
    return {1.0 - w, 0.0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0.0, 1.0 - w, w};
  }
  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return {1.0 - v - w, v, w};
}

}  // namespace

SurfaceDistance::SurfaceDistance(std::vector<Vec3> vertices, std::vector<Triangle> triangles)
    : vertices_(std::move(vertices)), triangles_(std::move(triangles)) {
  if (triangles_.empty()) throw std::invalid_argument("surface distance: no triangle");
  // Pseudo-normals: faces, edges (sum of the two faces'), vertices (angle-weighted).
  vertex_normal_.assign(vertices_.size(), Vec3::Zero());
  std::map<std::pair<int, int>, std::vector<int>> edges;
  double max_edge = 0.0;
  std::vector<double> lengths;
  for (size_t t = 0; t < triangles_.size(); ++t) {
    const Triangle& T = triangles_[t];
    const Vec3 &a = vertices_[static_cast<size_t>(T[0])], &b = vertices_[static_cast<size_t>(T[1])],
               &c = vertices_[static_cast<size_t>(T[2])];
    face_normal_.push_back((b - a).cross(c - a).normalized());
    triangle_box_.push_back({a.cwiseMin(b).cwiseMin(c), a.cwiseMax(b).cwiseMax(c)});
    for (int k = 0; k < 3; ++k) {
      const int i = T[static_cast<size_t>(k)], j = T[static_cast<size_t>((k + 1) % 3)],
                l = T[static_cast<size_t>((k + 2) % 3)];
      edges[{std::min(i, j), std::max(i, j)}].push_back(static_cast<int>(t));
      const double length =
          (vertices_[static_cast<size_t>(i)] - vertices_[static_cast<size_t>(j)]).norm();
      max_edge = std::max(max_edge, length);
      lengths.push_back(length);
      vertex_normal_[static_cast<size_t>(i)] +=
          corner_angle(vertices_[static_cast<size_t>(i)], vertices_[static_cast<size_t>(j)],
                       vertices_[static_cast<size_t>(l)]) *
          face_normal_.back();
    }
  }
  for (Vec3& n : vertex_normal_)
    if (n.norm() > 0.0) n.normalize();
  edge_normal_.resize(triangles_.size());
  for (size_t t = 0; t < triangles_.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int i = triangles_[t][static_cast<size_t>(k)],
                j = triangles_[t][static_cast<size_t>((k + 1) % 3)];
      const std::vector<int>& faces = edges.at({std::min(i, j), std::max(i, j)});
      if (faces.size() != 2)
        throw std::invalid_argument(
            "surface distance: the surface is not closed (an edge belongs to " +
            std::to_string(faces.size()) + " triangles)");
      edge_normal_[t][static_cast<size_t>(k)] = (face_normal_[static_cast<size_t>(faces[0])] +
                                                 face_normal_[static_cast<size_t>(faces[1])])
                                                    .normalized();
    }
  // Cells of the lower-quartile edge (each edge counted from both sides): a query then tests a
  // few triangles where a graded surface is refined (the median edge put tens of refined
  // triangles in one cell of the grid's meshed impactor), and a coarse triangle is listed in many
  // cells. No more than about 2e6 cells.
  const auto quartile = static_cast<long>(lengths.size() / 4);
  std::nth_element(lengths.begin(), lengths.begin() + quartile, lengths.end());
  Vec3 lo = vertices_.front(), hi = vertices_.front();
  for (const Vec3& v : vertices_) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  h_ = std::max(lengths[static_cast<size_t>(quartile)], std::cbrt((hi - lo).prod() / 2e6));
  inverse_h_ = 1.0 / h_;
  deep_ = max_edge;
  build_grid();
  flood_outside();
}

std::array<int, 3> SurfaceDistance::cell_of(const Vec3& p) const {
  std::array<int, 3> c{};
  for (int d = 0; d < 3; ++d)
    c[static_cast<size_t>(d)] = static_cast<int>(std::floor((p[d] - origin_[d]) * inverse_h_));
  return c;
}

long SurfaceDistance::cell_index(const std::array<int, 3>& c) const {
  for (int d = 0; d < 3; ++d)
    if (c[static_cast<size_t>(d)] < 0 || c[static_cast<size_t>(d)] >= dims_[static_cast<size_t>(d)])
      return -1;
  return (static_cast<long>(c[2]) * dims_[1] + c[1]) * dims_[0] + c[0];
}

// The grid spans the surface's box plus one empty cell on every side (the flood fill's border).
void SurfaceDistance::build_grid() {
  Vec3 lo = vertices_.front(), hi = vertices_.front();
  for (const Vec3& v : vertices_) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  box_ = {lo, hi};
  origin_ = lo - Vec3::Constant(h_);
  const auto top = cell_of(hi);  // the last cell that can hold a triangle, then one empty one
  for (size_t d = 0; d < 3; ++d) dims_[d] = top[d] + 2;
  const long n_cells = static_cast<long>(dims_[0]) * dims_[1] * dims_[2];
  std::vector<std::vector<int>> lists(static_cast<size_t>(n_cells));
  for (size_t t = 0; t < triangles_.size(); ++t) {
    Vec3 a = vertices_[static_cast<size_t>(triangles_[t][0])], b = a;
    for (int k : triangles_[t]) {
      a = a.cwiseMin(vertices_[static_cast<size_t>(k)]);
      b = b.cwiseMax(vertices_[static_cast<size_t>(k)]);
    }
    // The cells of the triangle's box that its plane crosses (a box meets the plane when its
    // centre lies within sum_d |n_d| h / 2 of it): a coarse tilted triangle's box holds many
    // cells its plane misses, and a point there would test it for nothing.
    const Vec3& n = face_normal_[t];
    const Vec3& v0 = vertices_[static_cast<size_t>(triangles_[t][0])];
    const double slab = 0.5 * h_ * n.cwiseAbs().sum() * (1.0 + 1e-9) + 1e-12 * h_;
    const auto c0 = cell_of(a), c1 = cell_of(b);
    for (int z = c0[2]; z <= c1[2]; ++z)
      for (int y = c0[1]; y <= c1[1]; ++y)
        for (int x = c0[0]; x <= c1[0]; ++x) {
          const Vec3 centre = origin_ + h_ * Vec3(x + 0.5, y + 0.5, z + 0.5);
          if (std::abs(n.dot(centre - v0)) > slab) continue;
          lists[static_cast<size_t>(cell_index({x, y, z}))].push_back(static_cast<int>(t));
        }
  }
  cell_start_.assign(static_cast<size_t>(n_cells) + 1, 0);
  for (long c = 0; c < n_cells; ++c)
    cell_start_[static_cast<size_t>(c) + 1] =
        cell_start_[static_cast<size_t>(c)] +
        static_cast<int>(lists[static_cast<size_t>(c)].size());
  cell_items_.clear();
  for (const auto& l : lists) cell_items_.insert(cell_items_.end(), l.begin(), l.end());
}

// DS.1: empty cells connected to the border through empty cells (faces) are outside.
void SurfaceDistance::flood_outside() {
  const long n_cells = static_cast<long>(cell_start_.size()) - 1;
  outside_.assign(static_cast<size_t>(n_cells), 0);
  auto empty = [&](long c) {
    return cell_start_[static_cast<size_t>(c)] == cell_start_[static_cast<size_t>(c) + 1];
  };
  std::vector<std::array<int, 3>> stack = {{0, 0, 0}};
  outside_[0] = 1;
  while (!stack.empty()) {
    const auto c = stack.back();
    stack.pop_back();
    for (int d = 0; d < 3; ++d)
      for (int s : {-1, 1}) {
        auto n = c;
        n[static_cast<size_t>(d)] += s;
        const long i = cell_index(n);
        if (i < 0 || outside_[static_cast<size_t>(i)] || !empty(i)) continue;
        outside_[static_cast<size_t>(i)] = 1;
        stack.push_back(n);
      }
  }
}

// The closest point of triangle t to p: its squared distance and weights.
double SurfaceDistance::closest(int t, const Vec3& p, std::array<double, 3>& w) const {
  const Triangle& T = triangles_[static_cast<size_t>(t)];
  const Vec3 &a = vertices_[static_cast<size_t>(T[0])], &b = vertices_[static_cast<size_t>(T[1])],
             &c = vertices_[static_cast<size_t>(T[2])];
  w = closest_weights(p, a, b, c);
  return (p - (w[0] * a + w[1] * b + w[2] * c)).squaredNorm();
}

// Squared distance from p to the box of cell c.
double SurfaceDistance::box_distance2(const Vec3& p, const std::array<int, 3>& c) const {
  double d2 = 0.0;
  for (int d = 0; d < 3; ++d) {
    const double lo = origin_[d] + h_ * c[static_cast<size_t>(d)], hi = lo + h_;
    const double out = p[d] < lo ? lo - p[d] : (p[d] > hi ? p[d] - hi : 0.0);
    d2 += out * out;
  }
  return d2;
}

// Ties (a shared edge or vertex) go to the lowest triangle: a result independent of the order. A
// triangle whose bounding box or plane is farther than the best so far can neither win nor tie:
// skipped (the same result, without the closest-point test).
void SurfaceDistance::consider(int t, const Vec3& p, Nearest& best) const {
  if (t == best.triangle) return;  // its distance is known (a hint, or a cell listed it already)
  const auto& box = triangle_box_[static_cast<size_t>(t)];
  const Vec3 out = (box[0] - p).cwiseMax(p - box[1]).cwiseMax(0.0);
  if (out.squaredNorm() > best.d2) return;
  // Nor can it when its plane is farther (the distance to the plane bounds it from below).
  const double plane = face_normal_[static_cast<size_t>(t)].dot(
      p - vertices_[static_cast<size_t>(triangles_[static_cast<size_t>(t)][0])]);
  if (plane * plane > best.d2) return;
  std::array<double, 3> w{};
  const double d2 = closest(t, p, w);
  if (d2 < best.d2 || (d2 == best.d2 && t < best.triangle)) best = {d2, t, w};
}

void SurfaceDistance::consider_cell(long cell, const Vec3& p, Nearest& best) const {
  for (int k = cell_start_[static_cast<size_t>(cell)];
       k < cell_start_[static_cast<size_t>(cell) + 1]; ++k)
    consider(cell_items_[static_cast<size_t>(k)], p, best);
}

// By cells alone (DS.2): a point within d of the surface has the cell of its closest surface point
// within the box [p - d, p + d], and that cell holds a triangle; a point inside lies in a cell
// that holds one or in an empty cell the flood fill did not reach. Neither: outside by more than d.
bool SurfaceDistance::any_cell_within(const Vec3& p, double d) const {
  const auto lo = cell_of(p - Vec3::Constant(d)), hi = cell_of(p + Vec3::Constant(d));
  for (int z = std::max(lo[2], 0); z <= std::min(hi[2], dims_[2] - 1); ++z)
    for (int y = std::max(lo[1], 0); y <= std::min(hi[1], dims_[1] - 1); ++y)
      for (int x = std::max(lo[0], 0); x <= std::min(hi[0], dims_[0] - 1); ++x) {
        const auto i = static_cast<size_t>(cell_index({x, y, z}));
        if (cell_start_[i] != cell_start_[i + 1] || !outside_[i]) return true;
      }
  return false;
}

// With allowances: a cell holding triangles counts within d plus its own allowance (a point within
// d of the lifted surface of a triangle is within d + allowance of its facet, which that cell or
// another within the same distance holds); an inside empty cell within d, as above.
bool SurfaceDistance::inside_or_within(const Vec3& p, double d) const {
  if (largest_allowance_ == 0.0) return any_cell_within(p, d);
  const double widest = d + largest_allowance_;
  const auto lo = cell_of(p - Vec3::Constant(widest)), hi = cell_of(p + Vec3::Constant(widest));
  for (int z = std::max(lo[2], 0); z <= std::min(hi[2], dims_[2] - 1); ++z)
    for (int y = std::max(lo[1], 0); y <= std::min(hi[1], dims_[1] - 1); ++y)
      for (int x = std::max(lo[0], 0); x <= std::min(hi[0], dims_[0] - 1); ++x) {
        const std::array<int, 3> cell{x, y, z};
        const auto i = static_cast<size_t>(cell_index(cell));
        const double reach = d + (cell_start_[i] != cell_start_[i + 1] ? cell_allowance_[i] : 0.0);
        if ((cell_start_[i] != cell_start_[i + 1] || !outside_[i]) &&
            box_distance2(p, cell) <= reach * reach)
          return true;
      }
  return false;
}

// LC.1: the clearance of a point outside the surface, min over triangles t of (distance to t -
// allowance_t): no point of any triangle's lift lies nearer. Only its sign is needed once it is
// not positive: the search returns the first value <= 0 it finds. `bound`, the nearest triangle's
// value, bounds it from above; a triangle can only do better when it lies within bound plus the
// largest allowance, so the cells of that box are searched, skipping a triangle whose box or
// plane is already too far.
double SurfaceDistance::lens_clearance(const Vec3& p, double bound, int* hint) const {
  double best = bound;
  const auto value = [&](int t) {
    std::array<double, 3> w{};
    return std::sqrt(closest(t, p, w)) - allowance_[static_cast<size_t>(t)];
  };
  // The triangle that decided this point last (a hint: the sign of the result does not depend
  // on it, and a positive result is the exact minimum either way).
  if (hint && *hint >= 0 && *hint < static_cast<int>(triangles_.size()))
    best = std::min(best, value(*hint));
  const double radius = bound + largest_allowance_;
  if (!(best > 0.0)) return best;  // within a lift already: its exact value is not needed
  const auto lo = cell_of(p - Vec3::Constant(radius)), hi = cell_of(p + Vec3::Constant(radius));
  for (int z = std::max(lo[2], 0); z <= std::min(hi[2], dims_[2] - 1); ++z)
    for (int y = std::max(lo[1], 0); y <= std::min(hi[1], dims_[1] - 1); ++y)
      for (int x = std::max(lo[0], 0); x <= std::min(hi[0], dims_[0] - 1); ++x) {
        const auto i = static_cast<size_t>(cell_index({x, y, z}));
        if (cell_start_[i] == cell_start_[i + 1]) continue;
        const double reach = best + cell_allowance_[i];
        if (reach <= 0.0 || box_distance2(p, {x, y, z}) >= reach * reach) continue;
        for (int k = cell_start_[i]; k < cell_start_[i + 1]; ++k) {
          const int t = cell_items_[static_cast<size_t>(k)];
          const double limit = best + allowance_[static_cast<size_t>(t)];
          if (limit <= 0.0) continue;
          const auto& box = triangle_box_[static_cast<size_t>(t)];
          const Vec3 out = (box[0] - p).cwiseMax(p - box[1]).cwiseMax(0.0);
          if (out.squaredNorm() >= limit * limit) continue;
          const double plane = face_normal_[static_cast<size_t>(t)].dot(
              p - vertices_[static_cast<size_t>(triangles_[static_cast<size_t>(t)][0])]);
          if (plane * plane >= limit * limit) continue;
          const double v = value(t);
          if (v < best) {
            best = v;
            if (hint) *hint = t;
          }
          if (!(best > 0.0)) return best;
        }
      }
  return best;
}

void SurfaceDistance::set_allowance(std::vector<double> per_triangle) {
  if (per_triangle.size() != triangles_.size())
    throw std::invalid_argument("surface distance: one allowance per triangle");
  allowance_ = std::move(per_triangle);
  largest_allowance_ = *std::max_element(allowance_.begin(), allowance_.end());
  cell_allowance_.assign(cell_start_.size() - 1, 0.0);
  for (size_t c = 0; c + 1 < cell_start_.size(); ++c)
    for (int k = cell_start_[c]; k < cell_start_[c + 1]; ++k)
      cell_allowance_[c] = std::max(
          cell_allowance_[c], allowance_[static_cast<size_t>(cell_items_[static_cast<size_t>(k)])]);
}

// Outside, and farther than `reach` from the surface, by p's cell alone: beyond the grid (which
// spans the surface's box) and farther than reach from the box, or in an empty outside cell with
// no surface within reach (DS.2).
bool SurfaceDistance::surely_outside(const Vec3& p, const std::array<int, 3>& c,
                                     double reach) const {
  const long own = cell_index(c);
  if (own < 0) {
    if (reach <= 0.0) return true;
    const Vec3 out = (box_[0] - p).cwiseMax(p - box_[1]).cwiseMax(0.0);
    return out.squaredNorm() > reach * reach;
  }
  const bool empty =
      cell_start_[static_cast<size_t>(own)] == cell_start_[static_cast<size_t>(own) + 1];
  if (!empty || !outside_[static_cast<size_t>(own)]) return false;
  return reach <= 0.0 || !any_cell_within(p, reach);
}

SurfaceDistance::Side SurfaceDistance::query(const Vec3& p, SurfacePoint& hit, int* hint,
                                             bool with_allowance, int* lens_hint) const {
  // With allowances, a point decided by its cells alone has a clearance above one cell.
  const double reach = with_allowance && largest_allowance_ > 0.0 ? largest_allowance_ + h_ : 0.0;
  const auto c = cell_of(p);
  if (surely_outside(p, c, reach)) return Side::outside;
  Nearest best;
  // A hint (any triangle) as the first candidate leaves the answer unchanged: the search below
  // stops only once every triangle nearer than the best has been considered, and prunes the
  // others sooner the nearer the best is.
  if (hint && *hint >= 0 && *hint < static_cast<int>(triangles_.size())) {
    std::array<double, 3> w{};
    best = {closest(*hint, p, w), *hint, w};
  }
  const long own = cell_index(c);
  if (own >= 0) consider_cell(own, p, best);
  // Ring k: the cells k steps from the own cell. After rings 0..k every triangle within k h of
  // p has been considered (its closest point lies within k cells of p's on each axis), so the
  // best is the nearest once it is within k h. Only the cells that overlap the cube of half-side
  // `best` about p can hold a nearer triangle: usually none beyond the own cell.
  // (A point beyond the grid lies within reach of it: its rings reach the far side by then.)
  const int widest = std::max({dims_[0], dims_[1], dims_[2]}) +
                     static_cast<int>(std::ceil(reach * inverse_h_)) + 1;
  for (int k = 1; k <= widest; ++k) {
    std::array<int, 3> lo{c[0] - k, c[1] - k, c[2] - k}, hi{c[0] + k, c[1] + k, c[2] + k};
    if (std::isfinite(best.d2)) {
      const double d = std::sqrt(best.d2);
      const auto a = cell_of(p - Vec3::Constant(d)), b = cell_of(p + Vec3::Constant(d));
      for (size_t e = 0; e < 3; ++e) {
        lo[e] = std::max({lo[e], a[e], 0});
        hi[e] = std::min({hi[e], b[e], dims_[e] - 1});
      }
    }
    for (int z = lo[2]; z <= hi[2]; ++z)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int x = lo[0]; x <= hi[0]; ++x) {
          const int ring = std::max({std::abs(x - c[0]), std::abs(y - c[1]), std::abs(z - c[2])});
          if (ring != k) continue;
          const std::array<int, 3> cell{x, y, z};
          const long i = cell_index(cell);
          if (i < 0 || box_distance2(p, cell) > best.d2) continue;
          consider_cell(i, p, best);
        }
    if (best.d2 <= k * k * h_ * h_) break;
  }
  if (hint) *hint = best.triangle;
  return finish(p, best, hit, with_allowance, lens_hint);
}

// The side of p by the pseudo-normal of the feature its nearest point (best) is on.
SurfaceDistance::Side SurfaceDistance::side_of(const Vec3& p, const Nearest& best) const {
  Vec3 q, normal;
  feature(best, q, normal);
  return (p - q).dot(normal) >= 0.0 ? Side::outside : Side::inside;
}

void SurfaceDistance::feature(const Nearest& best, Vec3& q, Vec3& normal) const {
  const Triangle& T = triangles_[static_cast<size_t>(best.triangle)];
  const std::array<double, 3>& w = best.weights;
  q = w[0] * vertices_[static_cast<size_t>(T[0])] + w[1] * vertices_[static_cast<size_t>(T[1])] +
      w[2] * vertices_[static_cast<size_t>(T[2])];
  // A vertex (one weight 1), an edge (one weight 0), or the face.
  normal = face_normal_[static_cast<size_t>(best.triangle)];
  for (int k = 0; k < 3; ++k) {
    const double wk = w[static_cast<size_t>(k)], w1 = w[static_cast<size_t>((k + 1) % 3)],
                 w2 = w[static_cast<size_t>((k + 2) % 3)];
    if (wk == 1.0)
      normal = vertex_normal_[static_cast<size_t>(T[static_cast<size_t>(k)])];
    else if (wk == 0.0 && w1 != 1.0 && w2 != 1.0)
      normal = edge_normal_[static_cast<size_t>(best.triangle)][static_cast<size_t>((k + 1) % 3)];
  }
}

SurfaceDistance::Side SurfaceDistance::finish(const Vec3& p, const Nearest& best, SurfacePoint& hit,
                                              bool with_allowance, int* lens_hint) const {
  Vec3 q, normal;
  feature(best, q, normal);
  const bool outside = (p - q).dot(normal) >= 0.0;
  if (outside) {
    const double d = std::sqrt(best.d2);
    const double clearance =
        with_allowance && !allowance_.empty()
            ? lens_clearance(p, d - allowance_[static_cast<size_t>(best.triangle)], lens_hint)
            : d;
    if (clearance > 0.0) {
      hit.depth = -clearance;
      hit.triangle = best.triangle;
      return Side::outside;
    }
  }
  hit.depth = outside ? -std::sqrt(best.d2) : std::sqrt(best.d2);
  hit.point = q;
  hit.normal = normal;
  hit.triangle = best.triangle;
  hit.weights = best.weights;
  if (outside) return Side::near;
  return hit.depth > deep_ ? Side::deep : Side::inside;
}

}  // namespace ccm
