// Which side of an edge-edge contact is admissible when the two edges start (nearly) in one
// plane (docs/hard-scenes.md, "Surfaces that start touching").
//
// An edge-edge constraint is g = sign * V(a, b, c, d) >= 0, V = (1/6) ((b - a) x (d - c)) . (c -
// a), and the CCD orients it by the side the edges start on: sign = sign(V(x_n)). Two bodies placed
// face to face (blocks stacked exactly on each other, a garment on a limb) start with their
// surface edges in one plane: V(x_n) is rounding noise and half of the pairs get the wrong sign,
// so the projection pushes those edges *through* each other while the node-face constraints push
// the other way; the projection runs to its cap and pumps energy into the bodies.
//
// The admissible side is where the surfaces face: edge (c, d) of body B lies outside body A, on
// the side of A's outward normal N_A at edge (a, b) (the sum of the normals of its faces), and A
// on the side of N_B. With N = N_A - N_B, moving (c, d) along N away from (a, b) changes V by
// (1/6) ((b - a) x (d - c)) . N per unit length, so
//
//     sign = sign(((b - a) x (d - c)) . N)
//
// whenever the start is ambiguous: the edges' lines are closer than the kept separation
// (|V| / (|e1 x e2| / 6) < g_sep) and the edge normal is not nearly tangent to the surfaces
// (|n . N| >= kMinAlignment |N|). Otherwise the start's sign stands.
#pragma once

#include <array>
#include <vector>

#include "engine/contact/dcr/contact_surface.hpp"

namespace ccm::dcr {

class EdgeOrientation {
 public:
  explicit EdgeOrientation(const SurfaceFeatures& f);
  // The sign of the constraint of edges ea and eb (global node ids; indices into f.edges:
  // edge_a, edge_b) at the start positions x0, given the kept separation [m].
  double sign(const SurfaceFeatures& f, int edge_a, int edge_b, const std::vector<Vec3>& x0,
              double separation) const;
  static constexpr double kMinAlignment = 0.5;

 private:
  Vec3 outward(const SurfaceFeatures& f, int edge, const std::vector<Vec3>& x) const;
  std::vector<std::array<int, 2>> faces_;  // per edge: up to two faces (-1: none)
};

}  // namespace ccm::dcr
