// Which points lie inside a closed, outward-oriented triangle surface, and for those, the
// closest point of the surface and the outward normal there: what a penalty contact against a
// meshed rigid body needs (rigid_surface_penalty.hpp; docs/rigid-bodies.md, "Penalty").
//
// The surface is fixed in its own frame (a rigid body's reference configuration). A uniform grid
// of cells of size h (the lower-quartile edge) holds every triangle in the cells its bounding
// box overlaps. A query visits the point's own cell, then rings of cells around it (ring k: the
// cells k steps away): after ring k every triangle within k h has been considered, so the search
// stops once the best is within k h, and a ring's cells farther than the best are skipped. The
// nearest triangle is exact (ties go to the lowest index), whatever the order or the hint. The
// side is that of the angle-weighted pseudo-normal at the closest feature (face, edge or vertex;
// Baerentzen & Aanaes, IEEE TVCG 11(3), 2005), exact for a closed manifold surface. Whether an
// empty cell is inside or outside is settled once by a flood fill from the grid's border through
// empty cells (DS.1): a point in an empty outside cell is outside at once. A point deeper than
// the longest edge inside is reported as deep (with its closest point).
#pragma once

#include <array>
#include <limits>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/mesh/tet_mesh.hpp"

namespace ccm {

struct SurfacePoint {
  double depth = 0.0;                            // > 0: inside, by this distance [m]
  Vec3 point = Vec3::Zero();                     // the closest point of the surface
  Vec3 normal = Vec3::Zero();                    // outward unit normal there (pseudo-normal)
  int triangle = -1;                             // the closest triangle
  std::array<double, 3> weights{1.0, 0.0, 0.0};  // the closest point's barycentric weights
};

class SurfaceDistance {
 public:
  // vertices and triangles (indices into vertices) of a closed surface, outward oriented.
  // Throws std::invalid_argument when it has no triangle or an edge is not shared by exactly two
  // triangles (not closed, or not manifold).
  SurfaceDistance(std::vector<Vec3> vertices, std::vector<Triangle> triangles);

  enum class Side { outside, near, inside, deep };
  // outside: `hit` untouched when p's cells alone decide it (with allowances, its clearance then
  // exceeds cell_size()); after a search, hit.depth is minus
  // p's clearance (LC.1: no point of the surface, or of any triangle's allowance above it, lies
  // nearer; the distance to the nearest triangle without allowances) and hit.triangle the nearest
  // triangle (the rest untouched). near (only with with_allowance): outside the triangles but
  // within some triangle's allowance, `hit` filled with depth = -distance to the nearest.
  // inside: `hit` filled. deep: filled, inside by more than deep_depth() (the longest edge).
  // `hint` (optional, in and out): a triangle likely nearest, such as this point's last answer;
  // it changes the cost, never the result, and is set to the nearest triangle whenever the search
  // reaches one.
  // `lens_hint` (optional, in and out): the triangle that last decided the point's clearance
  // (LC.1); like `hint`, it changes the cost only.
  Side query(const Vec3& p, SurfacePoint& hit, int* hint = nullptr, bool with_allowance = false,
             int* lens_hint = nullptr) const;

  // Whether p lies inside the surface or possibly within d (plus the allowance of the triangles
  // there) of it: true for every such point (and for some points up to a cell farther), false for
  // the rest. What a step bound counts as "can reach" (DS.2).
  bool inside_or_within(const Vec3& p, double d) const;

  // How far outside each triangle a point may lie and still count as near it: a curved surface's
  // lift above its facets (curved_surface.hpp). Zero for every triangle unless set.
  void set_allowance(std::vector<double> per_triangle);
  double largest_allowance() const { return largest_allowance_; }

  // The surface's bounding box (min, max corners): every point inside lies in it.
  const std::array<Vec3, 2>& box() const { return box_; }
  double cell_size() const { return h_; }
  double deep_depth() const { return deep_; }
  const std::vector<Triangle>& triangles() const { return triangles_; }
  const std::vector<Vec3>& vertices() const { return vertices_; }

 private:
  struct Nearest {
    double d2 = std::numeric_limits<double>::infinity();
    int triangle = -1;
    std::array<double, 3> weights{};
  };
  double closest(int t, const Vec3& p, std::array<double, 3>& w) const;
  void consider(int t, const Vec3& p, Nearest& best) const;
  void consider_cell(long cell, const Vec3& p, Nearest& best) const;
  double box_distance2(const Vec3& p, const std::array<int, 3>& c) const;
  bool surely_outside(const Vec3& p, const std::array<int, 3>& c, double reach) const;
  bool any_cell_within(const Vec3& p, double d) const;
  double lens_clearance(const Vec3& p, double bound, int* hint) const;
  void feature(const Nearest& best, Vec3& q, Vec3& normal) const;
  Side side_of(const Vec3& p, const Nearest& best) const;
  Side finish(const Vec3& p, const Nearest& best, SurfacePoint& hit, bool with_allowance,
              int* lens_hint) const;
  long cell_index(const std::array<int, 3>& c) const;
  std::array<int, 3> cell_of(const Vec3& p) const;
  void build_grid();
  void flood_outside();

  std::vector<Vec3> vertices_;
  std::vector<Triangle> triangles_;
  std::vector<Vec3> face_normal_;
  std::vector<std::array<Vec3, 2>> triangle_box_;  // per triangle: its bounding box (min, max)
  std::vector<std::array<Vec3, 3>> edge_normal_;   // per triangle: edge (k, k+1) pseudo-normal
  std::vector<Vec3> vertex_normal_;
  std::array<Vec3, 2> box_{Vec3::Zero(), Vec3::Zero()};
  double h_ = 0.0, inverse_h_ = 0.0;
  double deep_ = 0.0;  // depth beyond which a point is `deep`: the longest edge
  Vec3 origin_ = Vec3::Zero();
  std::array<int, 3> dims_{};
  std::vector<int> cell_start_;  // CSR: triangles of cell c are cell_items_[start[c], start[c+1])
  std::vector<int> cell_items_;
  std::vector<char> outside_;      // per empty cell: reachable from the border through empty cells
  std::vector<double> allowance_;  // per triangle (empty: none)
  std::vector<double> cell_allowance_;  // per cell: the largest of its triangles'
  double largest_allowance_ = 0.0;
};

}  // namespace ccm
