// Narrow phase of the DCR contact search: the DCR constraint volumes, their gradients, and
// continuous collision detection over a step (docs/contact-method.md §1.1 and §3; thesis 2.4.2,
// fig. 2-3).
//
// CCD. Every position moves linearly over the step: x(tau) = x0 + tau (x1 - x0), tau in [0, 1].
// The four points are coplanar exactly where 6 g(tau) = 0, a cubic in tau (Provot 1997; Bridson,
// Fedkiw & Anderson 2002). A root is a hit when, at that time, the node lies in the triangle
// (barycentric weights of its projection on the triangle's plane all within [-tol, 1 + tol]) or
// the edges cross (closest-point parameters s, t of the two lines within [-tol, 1 + tol]).
//
// Robustness (what is done about near-degenerate cases):
//  - Everything is computed relative to vertex a (of the face, or of the first edge): each
//    relative vector is one rounded subtraction of the inputs, so far-from-origin coordinates
//    cost no digits, and 6 g(tau) is evaluated from the interpolated relative vectors (exact at
//    tau = 0 and 1), not from expanded cubic coefficients.
//  - Roots are not taken from a closed-form cubic: [0, 1] is split at the critical points of
//    the cubic into monotone pieces, taken in time order, and each sign change is bracketed to a
//    few ulps (false position with the Illinois modification, bisection as safeguard). A linear
//    relative motion thus gets its time of impact to rounding.
//  - The rounding noise of 6 g = (U x V) . W is bounded by eps = 64 u |U| |V| |W| (u the unit
//    roundoff, each norm its largest over the step). Wherever |6 g| <= eps (the "window" of
//    a root: a grazing touch without sign change, a start or end on the plane, or a crossing so
//    shallow that its time is uncertain) the inclusion test is not made at one time but over the
//    whole window: with the plane normal n frozen, the barycentric conditions (or s, t
//    conditions) are quadratics in tau, so the first time in the window that satisfies them all
//    is the window's start or a root of one of them, and those few times are tested in order.
//    The time tested first is the refined root itself when there is a sign change, so a
//    well-conditioned hit keeps its exact time; inside a window the tolerance gets 1e-10 more.
//    (Around a root the window is found by stepping out from it, so it may be a little wider
//    than the exact set |6 g| <= eps; wider is only more conservative.)
//    This is conservative: a true hit is not lost to rounding, at the price of reporting pairs
//    that come within rounding noise of touching.
//  - Coplanar motion (6 g within eps over the whole step) is the window [0, 1]: the node moving
//    in the face's plane is a hit when, and from the first time, it is inside the triangle; two
//    coplanar edges are a hit from the first time they cross in the plane.
//  - A start on the plane inside the triangle is a hit at toi = 0, whatever the direction of the
//    motion: CCD reports touching, the response decides from the sign of g.
//  - No hit is reported for a degenerate triangle (area below 1e-12 L^2) or for (near-)parallel
//    edges (|e1 x e2| < 1e-8 |e1| |e2|): their gradient vanishes, and node-face pairs cover them.
//  - No minimum separation is built in: the response projects to a separation delta_sep > 0
//    (docs/contact-method.md §3), and the broad phase's inflation keeps such pairs as candidates.
//  - A node already inside at the start that stays inside has no root and is not a hit; the
//    response can find it from the sign of g.
#pragma once

#include <optional>

#include "engine/core/types.hpp"

namespace ccm::dcr {

struct NodeFaceHit {
  double toi;            // time of impact in [0, 1]
  double w_a, w_b, w_c;  // barycentric weights of the node's projection at toi (sum 1)
};

struct EdgeEdgeHit {
  double toi;   // time of impact in [0, 1]
  double s, t;  // point on edge a: (1 - s) a + s b; on edge b: (1 - t) c + t d (at toi)
};

// Node p against face (a, b, c); 0 and 1 mark the positions at the start and the end of the step.
std::optional<NodeFaceHit> node_face_ccd(const Vec3& p0, const Vec3& a0, const Vec3& b0,
                                         const Vec3& c0, const Vec3& p1, const Vec3& a1,
                                         const Vec3& b1, const Vec3& c1, double tol);

// Edge (a, b) against edge (c, d).
std::optional<EdgeEdgeHit> edge_edge_ccd(const Vec3& a0, const Vec3& b0, const Vec3& c0,
                                         const Vec3& d0, const Vec3& a1, const Vec3& b1,
                                         const Vec3& c1, const Vec3& d1, double tol);

// g = (1/6) ((b - a) x (c - a)) . (p - a) = (A/3) d: positive when p is on the outward side of the
// face (a, b, c) (counter-clockwise seen from outside), d the signed height, A the area.
double node_face_volume(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

// grad = [dg/dp, dg/da, dg/db, dg/dc]:
//   dg/dp = (1/6) (b - a) x (c - a),  dg/db = (1/6) (c - a) x (p - a),
//   dg/dc = (1/6) (p - a) x (b - a),  dg/da = -(dg/dp + dg/db + dg/dc).
void node_face_volume_gradient(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c,
                               Vec3 grad[4]);

// g = (1/6) (e1 x e2) . r with e1 = b - a, e2 = d - c, r = c - a. No intrinsic inside: the
// admissible sign is the sign at the start of the step.
double edge_edge_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// grad = [dg/da, dg/db, dg/dc, dg/dd]:
//   dg/da = -(1/6) (e2 x r + e1 x e2),  dg/db = (1/6) e2 x r,
//   dg/dc = (1/6) (e1 x e2 - r x e1),   dg/dd = (1/6) r x e1.
void edge_edge_volume_gradient(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
                               Vec3 grad[4]);

}  // namespace ccm::dcr
