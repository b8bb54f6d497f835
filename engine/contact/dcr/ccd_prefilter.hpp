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

}  // namespace ccm::dcr
