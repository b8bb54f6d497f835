// A curved closed triangle surface: the smooth surface a faceted mesh of a smooth part stands
// for, with its sharp edges kept (docs/rigid-bodies.md, "The curved surface"). What a penalty
// against a meshed rigid body measures its depth to (rigid_surface_penalty.hpp).
//
// Corner normals: the triangles around a vertex fall into smoothing groups, joined across every
// edge whose two faces' normals differ by no more than the crease angle; a corner's normal is the
// normalised sum of its group's face normals n_f, each weighted by Max's weight
//   n = normalise(sum_f sin(a_f) / (|e_f1| |e_f2|) n_f)                                   (NG.0)
// (a_f the face's angle at the corner, e_f1, e_f2 its edges there; N. Max, Journal of Graphics
// Tools 4(2), 1999): exact when the vertex and its neighbours lie on a sphere, whatever the
// triangles' sizes and shapes. Angle weights are not: on the grid's graded impactor their normals
// tilted the patches enough to move the artifact's final kinetic energy by 2.6 % (point 6 of the
// default grid, mean of dt_safety 0.6-0.9; -0.6 % with the exact normals). Each triangle
// (v_0, v_1, v_2) becomes a
// quadratic Nagata patch (T. Nagata, Computer Aided Geometric Design 22(4), 2005, eq. 7 and 13):
// over barycentric weights b,
//   x(b) = sum_i b_i v_i - c_01 b_0 b_1 - c_12 b_1 b_2 - c_20 b_2 b_0                     (NG.1)
// each edge (i, j) a parabola through its ends normal to both corner normals n_i, n_j:
//   c_ij = dd / (1 - dc) v + d / dc dv,  v = (n_i + n_j) / 2,  dv = (n_i - n_j) / 2,
//   d = (v_j - v_i) . v,  dd = (v_j - v_i) . dv,  dc = n_i . dv                          (NG.2)
// (c_ij = 0 where the two normals agree). c_ij is the same from either triangle of an edge, so
// the patches meet along every edge that is not a crease; a facet whose corners all keep its face
// normal (a flat face's, or every facet at crease angle 0) is the flat triangle itself. On a
// sphere an edge's parabola is within O(h^4 / R^3) of the great circle (the facets' sag is
// h^2 / 8R).
//
// The depth of a point x: its foot point on the patch by Gauss-Newton from the nearest point of
// the flat triangle (surface_distance.hpp), b <- b + (J^T J)^-1 J^T (x - x(b)), J = dx/d(b_1, b_2)
// (three iterations), then with the patch's outward normal n = normalise(J_1 x J_2) there
//   depth = (x(b) - x) . n                                                                (NG.3)
// A foot that leaves its triangle (a weight below 0) moves to the triangle across that edge and
// is sought there again, up to four times (NG.5): the foot on the patches as one surface, not on
// the nearest facet's patch extended.
// How far the patch lies from its facet: |x(b) - p| <= max |c_ij| (b_0 b_1 + b_1 b_2 + b_2 b_0)
// <= max |c_ij| / 3                                                                       (NG.4)
#pragma once

#include <array>
#include <vector>

#include "engine/contact/penalty/surface_distance.hpp"
#include "engine/core/types.hpp"
#include "engine/mesh/tet_mesh.hpp"

namespace ccm {

class CurvedSurface {
 public:
  // The same vertices and outward-oriented triangles as the surface's SurfaceDistance;
  // crease_degrees in [0, 180) (default kDefaultCreaseAngle, engine/core/penalty_mode.hpp).
  // Throws std::invalid_argument for an edge not shared by exactly two triangles.
  CurvedSurface(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                double crease_degrees);

  // Whether triangle t is its flat facet (every c_ij zero).
  bool flat(int t) const { return flat_[static_cast<size_t>(t)] != 0; }
  bool all_flat() const { return all_flat_; }
  // Per triangle, how far its patch can lie from its facet (NG.4): a point farther than that
  // from the facet is not below the patch. Zero on a flat facet.
  const std::vector<double>& allowances() const { return allowance_; }

  // NG.3 for x whose nearest flat point lies on triangle `flat_hit.triangle` at weights
  // `flat_hit.weights`: fills `hit` with the depth (negative outside), the patch normal, and the
  // point where the line through x along that normal meets the facet's plane, with its
  // (unclamped) barycentric weights: a force along n at x and its opposite there act along one
  // line. A flat facet returns flat_hit.
  // `foot_weights` (optional): the foot's weights b_1, b_2 on hit.triangle.
  void evaluate(const Vec3& x, const SurfacePoint& flat_hit, SurfacePoint& hit,
                std::array<double, 2>* foot_weights = nullptr) const;

  // NG.3 and NG.5 from a known foot (triangle, weights b_1, b_2): a point's foot of the step
  // before, tracked. False when the foot does not end on a curved patch within the walks (then
  // search with evaluate()); else `hit` and `foot_weights` as evaluate() fills them.
  bool track(const Vec3& x, int triangle, std::array<double, 2> from, SurfacePoint& hit,
             std::array<double, 2>& foot_weights) const;

  struct PatchPoint {
    Vec3 x, t1, t2;  // NG.1 and its derivatives along b_1, b_2
  };

 private:
  enum class Foot { on_patch, off_patch, folded };
  Foot walk(const Vec3& x, size_t t, double b1, double b2, SurfacePoint& hit,
            std::array<double, 2>* foot_weights) const;
  void foot(size_t t, const Vec3& x, double& b1, double& b2, PatchPoint& P) const;
  std::array<Vec3, 3> corners(size_t t) const;
  std::array<double, 3> projected_inside(size_t t, const Vec3& x) const;

  std::vector<Vec3> vertices_;
  std::vector<Triangle> triangles_;
  std::vector<Vec3> face_normal_;
  std::vector<std::array<Vec3, 3>> edge_c_;    // per triangle: c_01, c_12, c_20 (NG.2)
  std::vector<std::array<int, 3>> neighbour_;  // per triangle: across edge (k, k + 1)
  std::vector<char> flat_;
  std::vector<double> allowance_;
  bool all_flat_ = true;
};

}  // namespace ccm
