// Evidence for the smoothed rigid surface (engine/contact/penalty/curved_surface.hpp, NG.1-NG.4):
// on a coarse meshed sphere the smoothed depth is the sphere's closed form R - |x| far closer than
// the flat facets' depth; a box keeps its facets (crease angle below 90 degrees); every smoothed
// point lies within NG.4's reach of the flat surface; the force line meets the facet's plane.
#include <Eigen/Geometry>
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "engine/contact/penalty/curved_surface.hpp"
#include "engine/contact/penalty/surface_distance.hpp"
#include "engine/core/penalty_mode.hpp"
#include "engine/mesh/boundary_surface.hpp"
#include "tests/support/contact_scenes.hpp"
#include "tests/support/models.hpp"

using namespace ccm;

namespace {

// A sphere (radius R, centre 0) meshed by Gmsh at `edge`, its distance grid with the curved
// surface's lifts.
struct CurvedSphere {
  explicit CurvedSphere(double edge, double R = 1.0)
      : ball(test::gmsh_sphere(R, edge, Vec3::Zero())),
        distance(ball.nodes, extract_boundary(ball.tets)),
        curved(distance.vertices(), distance.triangles(), 45.0) {
    distance.set_allowance(curved.allowances());
  }
  TetMesh ball;
  SurfaceDistance distance;
  CurvedSurface curved;
};

struct Depths {
  double flat_error = 0.0, smooth_error = 0.0;  // largest |depth - (R - |x|)|
  double outside_error = 0.0;   // largest R - |x| of a point found outside every allowance
  int points = 0, outside = 0;  // points evaluated; points outside every allowance
};

// Points within `shell` of a sphere of radius R (inside and out), their depth below the flat
// facets and below the smoothed surface against R - |x|.
Depths sphere_depths(double R, double edge, double shell, int samples) {
  const CurvedSphere sphere(edge, R);
  const SurfaceDistance& d = sphere.distance;
  const CurvedSurface& smooth = sphere.curved;
  std::mt19937 rng(5);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(-shell, shell);
  Depths out;
  for (int i = 0; i < samples; ++i) {
    const Vec3 x = Vec3(g(rng), g(rng), g(rng)).normalized() * (R + u(rng));
    SurfacePoint flat, hit;
    const auto side = d.query(x, flat, nullptr, true);
    const double exact = R - x.norm();
    if (side == SurfaceDistance::Side::outside) {
      // Beyond every allowance: outside the curved surface. Its error: how deep it is in truth.
      out.smooth_error = std::max(out.smooth_error, exact);
      out.outside_error = std::max(out.outside_error, exact);
      ++out.outside;
      continue;
    }
    smooth.evaluate(x, flat, hit);
    out.flat_error = std::max(out.flat_error, std::abs(flat.depth - exact));
    out.smooth_error = std::max(out.smooth_error, std::abs(hit.depth - exact));
    // The force line x + tau n meets the facet's plane at hit.point, weights summing to 1.
    const auto& T = d.triangles()[static_cast<size_t>(hit.triangle)];
    Vec3 q = Vec3::Zero();
    for (int a = 0; a < 3; ++a)
      q += hit.weights[static_cast<size_t>(a)] *
           d.vertices()[static_cast<size_t>(T[static_cast<size_t>(a)])];
    CHECK((q - hit.point).norm() < 1e-9 * R);
    CHECK((hit.point - x).cross(hit.normal).norm() < 1e-9 * R);
    ++out.points;
  }
  return out;
}

}  // namespace

// The sag of a facet of edge h on a sphere of radius R is about h^2 / 8R (2.5 % of R at the
// coarse mesh's h = 0.45 R); NG.1 reproduces the sphere to second order, so its error is a small
// fraction of that. Points within a tenth of the edge of the sphere.
TEST_CASE("smoothed surface: a coarse meshed sphere's depth against R - |x|",
          "[rigid-body][penalty][phong]") {
  for (const double edge : {0.4, 0.2}) {
    const Depths d = sphere_depths(1.0, edge, 0.1 * edge, 2000);
    INFO("edge " << edge << ": flat " << d.flat_error << ", smoothed " << d.smooth_error
                 << ", outside " << d.outside << " (" << d.outside_error << ")");
    CHECK(d.points + d.outside == 2000);
    CHECK(d.points > 1000);
    CHECK(d.smooth_error < 0.25 * d.flat_error);
  }
}

// NG.0: Max's weights give the exact normal at a vertex whose neighbours lie on one sphere with
// it, whatever the triangles' shapes (angle weights missed by up to 0.2 rad on this mesh). Just
// outside each vertex of the coarse meshed sphere, the smoothed surface's normal is the radius's
// direction, and the depth R - |x|, to round-off.
TEST_CASE("smoothed surface: a meshed sphere's corner normals are its radii",
          "[rigid-body][penalty][phong]") {
  const CurvedSphere sphere(0.4);
  double normal_error = 0.0, depth_error = 0.0;
  for (const Triangle& t : sphere.distance.triangles()) {
    const Vec3& v = sphere.distance.vertices()[static_cast<size_t>(t[0])];
    const Vec3 x = 1.001 * v;
    SurfacePoint flat, hit;
    REQUIRE(sphere.distance.query(x, flat, nullptr, true) != SurfaceDistance::Side::outside);
    sphere.curved.evaluate(x, flat, hit);
    normal_error = std::max(normal_error, (hit.normal - v.normalized()).norm());
    depth_error = std::max(depth_error, std::abs(hit.depth - (v.norm() - x.norm())));
  }
  INFO("largest normal error " << normal_error << ", depth error " << depth_error);
  CHECK(normal_error < 1e-9);
  CHECK(depth_error < 1e-9);
}

TEST_CASE("smoothed surface: a box keeps its flat faces and sharp edges",
          "[rigid-body][penalty][phong]") {
  const TetMesh box = structured_box(Vec3(0.2, 0.3, 0.4), 4, 6, 8);
  const auto triangles = extract_boundary(box.tets);
  const SurfaceDistance d(box.nodes, triangles);
  for (const double crease : {0.0, 45.0, 89.0}) {
    const CurvedSurface smooth(d.vertices(), d.triangles(), crease);
    CHECK(smooth.all_flat());
    for (const double a : smooth.allowances()) CHECK(a == 0.0);
  }
  // At 91 degrees the edges are smoothed: the corners' facets are no longer flat.
  const CurvedSurface rounded(d.vertices(), d.triangles(), 91.0);
  CHECK_FALSE(rounded.all_flat());
}

// CL.1 and LC.1 (rigid_surface_penalty.cpp, surface_distance.cpp): a point found outside with
// clearance g stays outside anywhere within g of that place. Random places around a coarse curved
// sphere and random moves up to the clearance, in every direction.
TEST_CASE("smoothed surface: a point within its clearance stays outside",
          "[rigid-body][penalty][phong]") {
  const CurvedSphere sphere(0.3);
  const SurfaceDistance& d = sphere.distance;
  std::mt19937 rng(3);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int cleared = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 X0 = Vec3(g(rng), g(rng), g(rng)).normalized() * (1.0 + 0.2 * u(rng));
    SurfacePoint hit;
    if (d.query(X0, hit, nullptr, true) != SurfaceDistance::Side::outside) continue;
    if (!(hit.depth < 0.0)) continue;  // decided by cells alone: no distance
    const double radius = -hit.depth;
    ++cleared;
    for (int j = 0; j < 5; ++j) {
      const Vec3 X = X0 + Vec3(g(rng), g(rng), g(rng)).normalized() * radius * u(rng);
      SurfacePoint at;
      CHECK(d.query(X, at, nullptr, true) == SurfaceDistance::Side::outside);
    }
  }
  CHECK(cleared > 300);
}

// NG.5: a point's foot tracked from where it was a small move before gives the depth a fresh
// search gives (the same foot on the same patches, to the Gauss-Newton's convergence: 1e-9 of R),
// on a coarse sphere whose feet cross facet edges.
TEST_CASE("smoothed surface: a tracked foot gives the searched depth",
          "[rigid-body][penalty][phong]") {
  const CurvedSphere sphere(0.3);
  const SurfaceDistance& d = sphere.distance;
  const CurvedSurface& smooth = sphere.curved;
  std::mt19937 rng(9);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(-0.02, 0.02);
  int tracked = 0, moved_across = 0, other_side = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 x0 = Vec3(g(rng), g(rng), g(rng)).normalized() * (1.0 + u(rng));
    SurfacePoint flat, hit;
    if (d.query(x0, flat, nullptr, true) == SurfaceDistance::Side::outside) continue;
    std::array<double, 2> foot{};
    smooth.evaluate(x0, flat, hit, &foot);
    const Vec3 x1 = x0 + Vec3(u(rng), u(rng), u(rng));  // up to 3.5 cm: a tenth of an edge
    SurfacePoint flat1, fresh, again;
    if (d.query(x1, flat1, nullptr, true) == SurfaceDistance::Side::outside) continue;
    smooth.evaluate(x1, flat1, fresh);
    std::array<double, 2> foot1{};
    if (!smooth.track(x1, hit.triangle, foot, again, foot1)) continue;
    ++tracked;
    if (again.triangle != hit.triangle) ++moved_across;
    CHECK(std::abs(again.depth - fresh.depth) < 1e-9);
    // The patches meet along edges but their normals need not (NG.1 is C0): a foot on an edge
    // may be found from either side.
    if ((again.normal - fresh.normal).norm() > 1e-6) ++other_side;
  }
  CHECK(tracked > 1000);
  CHECK(other_side < tracked / 20);
  CHECK(moved_across > 50);
}
