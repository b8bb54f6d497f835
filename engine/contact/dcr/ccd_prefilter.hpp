// A cheap, conservative test that lets the DCR skip the exact continuous collision detection
// (ccd.hpp) of an edge pair that cannot cross during the step (docs/hard-scenes.md, "Resting
// contact").
//
// Over the step every node moves on a straight line, x(tau) = x0 + tau (x1 - x0). A point of
// edge (a, b) at parameter s moves by (1 - s) da + s db, so by at most D_ab = max(|da|, |db|) at
// any tau; likewise D_cd for the other edge. The distance between any two points of the edges
// therefore never falls below d0 - D_ab - D_cd, with d0 the distance of the two segments at the
// start. The CCD accepts a crossing slightly outside the edges (parameter tolerance tol, i.e.
// tol x the edge's length) and reports pairs within rounding noise of touching; with those
// allowances,
//
//     d0 > D_ab + D_cd + kSlack (|b - a| + |d - c|)      =>  the CCD finds no hit,
//
// kSlack = 1e-5, ten times the CCD's 1e-6 inclusion tolerance (ccd.hpp) and far above its
// rounding window (64 u times the lengths). A resting contact keeps two surfaces 1e-4 of an
// edge apart (the DCR's kept separation) while moving far less than that per step, so nearly
// all of its edge pairs are decided here without the cubic.
#pragma once

#include "engine/core/types.hpp"

namespace ccm::dcr {

// Distance between the segments [a, b] and [c, d] (closest points, clamped to the segments).
double segment_distance(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// True when the edges (a, b) and (c, d) moving linearly from *0 to *1 may cross during the step
// (the CCD must decide); false when they provably stay apart.
bool edges_may_cross(const Vec3& a0, const Vec3& b0, const Vec3& c0, const Vec3& d0, const Vec3& a1,
                     const Vec3& b1, const Vec3& c1, const Vec3& d1);

// The margin of the prefilters, a fraction of the features' edge lengths (see above).
inline constexpr double kPrefilterSlack = 1e-5;

// Distance from p to the triangle (a, b, c) (closest point on the triangle, Ericson 5.1.5).
double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

// The node-face counterpart of edges_may_cross, for the DCR's node-face test (a CCD hit, or a
// persistent contact: at the end of the step within `proximity` of the face's plane with its
// projection inside the face, barycentric tolerance 1e-6). A point of the face moves by at most
// D_f = max(|da|, |db|, |dc|) over the step and the node by D_p = |dp|, so with d0 the distance
// of the node to the triangle at the start,
//
//     d0 > D_p + D_f + proximity + kPrefilterSlack (|b - a| + |c - b| + |a - c|)
//
// means the node is farther than proximity (plus the inclusion allowances) from the triangle at
// every time of the step: no CCD hit and no persistent contact. Returns false then.
bool node_face_may_touch(const Vec3& p0, const Vec3& a0, const Vec3& b0, const Vec3& c0,
                         const Vec3& p1, const Vec3& a1, const Vec3& b1, const Vec3& c1,
                         double proximity);

// The same two tests from a start distance d0 computed by the caller (segment_distance,
// point_triangle_distance at the start positions), and their slack terms; the node-face test
// from its parts, D_p + D_f (node_face_reach) and the face's slack (face_slack), for a caller
// that asks it with more than one proximity.
double edge_pair_slack(const Vec3& a0, const Vec3& b0, const Vec3& c0, const Vec3& d0);
double face_slack(const Vec3& a0, const Vec3& b0, const Vec3& c0);
bool edges_may_cross_from(double distance, const Vec3& a0, const Vec3& b0, const Vec3& c0,
                          const Vec3& d0, const Vec3& a1, const Vec3& b1, const Vec3& c1,
                          const Vec3& d1);
double node_face_reach(const Vec3& p0, const Vec3& a0, const Vec3& b0, const Vec3& c0,
                       const Vec3& p1, const Vec3& a1, const Vec3& b1, const Vec3& c1);
bool node_face_may_touch_within(double distance, double reach, double slack, double proximity);

// A second exact no-hit test, from the CCD's own cubic instead of a distance: the CCD's four
// points can only meet where they are coplanar, 6 g(tau) = (U x V) . W = 0 (two edges: U = b - a,
// V = d - c, W = c - a; a node and a face: U = b - a, V = c - a, W = p - a; each moving linearly,
// ccd.hpp). With X(tau) = X0 + tau dX the triple product is multilinear, so over the step
//     |6 g(tau) - 6 g(0)| <= (|U| + |dU|)(|V| + |dV|)(|W| + |dW|) - |U| |V| |W|.
// The CCD reports a hit only at a root of 6 g or inside its rounding window, |6 g| <= 64 u x the
// same product of the largest norms (ccd.hpp). Hence
//     |6 g(0)| > the variation bound + 1e-12 x (|U| + |dU|)(|V| + |dV|)(|W| + |dW|)
// (the margin is 4e3 times that window and covers the rounding of this test) means the CCD finds
// no hit, and the functions return true. They need no distance: two resting surfaces a kept
// separation apart stay off the plane of each of their near pairs (a node and a face, two edges
// crossing at an angle) by far more than they move in a step.
bool edges_stay_off_plane(const Vec3& a0, const Vec3& b0, const Vec3& c0, const Vec3& d0,
                          const Vec3& a1, const Vec3& b1, const Vec3& c1, const Vec3& d1);
bool node_stays_off_face_plane(const Vec3& p0, const Vec3& a0, const Vec3& b0, const Vec3& c0,
                               const Vec3& p1, const Vec3& a1, const Vec3& b1, const Vec3& c1);

}  // namespace ccm::dcr
