// Swept, inflated axis-aligned boxes of the contact surface's features over one step
// (docs/contact-method.md §4, thesis 2.4):
//   node box  = [min(x_n, x_{n+1}), max(x_n, x_{n+1})]  (per coordinate),
//   edge/face = the hull of its nodes' boxes,
// every box then inflated by the same `inflation` on every side. The broad phase's grid search
// and its cached filter both get their boxes from feature_boxes(), so the two see bit-identical
// boxes and agree exactly on which pairs overlap.
#pragma once

#include <algorithm>
#include <array>
#include <span>
#include <vector>

#include "engine/contact/dcr/contact_surface.hpp"
#include "engine/contact/dcr/thread_chunks.hpp"
#include "engine/core/types.hpp"

namespace ccm::dcr {

struct Box {
  std::array<double, 3> lo, hi;
};

// Closed intervals: touching boxes overlap.
inline bool overlap(const Box& a, const Box& b) {
  return a.lo[0] <= b.hi[0] && b.lo[0] <= a.hi[0] && a.lo[1] <= b.hi[1] && b.lo[1] <= a.hi[1] &&
         a.lo[2] <= b.hi[2] && b.lo[2] <= a.hi[2];
}

// overlap() without its short circuit: the same answer, one predictable branch for the caller.
// The comparisons as integers, joined by a bitwise and: no short circuit (clang's
// -Wbitwise-instead-of-logical asks for this spelling of the intent).
inline bool overlap_branchless(const Box& a, const Box& b) {
  const auto le = [](double x, double y) { return static_cast<int>(x <= y); };
  return (le(a.lo[0], b.hi[0]) & le(b.lo[0], a.hi[0]) & le(a.lo[1], b.hi[1]) &
          le(b.lo[1], a.hi[1]) & le(a.lo[2], b.hi[2]) & le(b.lo[2], a.hi[2])) != 0;
}

// The largest side of a box.
inline double largest_side(const Box& b) {
  return std::max({b.hi[0] - b.lo[0], b.hi[1] - b.lo[1], b.hi[2] - b.lo[2]});
}

// The median over `boxes` of their largest side, 0 when there is none (the grid's cell and the
// broad phase's skin are both sized by it over the face boxes); `scratch` is reused.
double median_largest_side(std::span<const Box> boxes, std::vector<double>& scratch);

// True when `inner` lies inside `outer` (closed).
inline bool contains(const Box& outer, const Box& inner) {
  return outer.lo[0] <= inner.lo[0] && outer.lo[1] <= inner.lo[1] && outer.lo[2] <= inner.lo[2] &&
         inner.hi[0] <= outer.hi[0] && inner.hi[1] <= outer.hi[1] && inner.hi[2] <= outer.hi[2];
}

// The faces and edges of a surface in local node indices (into SurfaceFeatures::nodes).
struct LocalTopology {
  std::vector<std::array<int, 3>> faces;
  std::vector<std::array<int, 2>> edges;
};

// Throws std::invalid_argument when a face or edge uses a node missing from f.nodes.
LocalTopology local_topology(const SurfaceFeatures& f);

[[noreturn]] void throw_no_position(int node);
[[noreturn]] void throw_not_finite(int node);

// The swept box of surface node i (index into f.nodes), not inflated; throws as below. Inline:
// a box returned from a call was written in scalars and read back in vectors, a store-forwarding
// stall that took a third of the broad phase's node sweep.
inline Box swept_node_box(const SurfaceFeatures& f, std::span<const Vec3> x_start,
                          std::span<const Vec3> x_end, std::size_t i) {
  const int n = f.nodes[i];
  if (n < 0 || static_cast<std::size_t>(n) >= std::min(x_start.size(), x_end.size()))
    throw_no_position(n);
  const Vec3& a = x_start[static_cast<size_t>(n)];
  const Vec3& c = x_end[static_cast<size_t>(n)];
  if (!a.allFinite() || !c.allFinite()) throw_not_finite(n);
  Box b;
  for (size_t d = 0; d < 3; ++d) {
    const auto k = static_cast<Eigen::Index>(d);
    b.lo[d] = std::min(a[k], c[k]);
    b.hi[d] = std::max(a[k], c[k]);
  }
  return b;
}

// The swept box of every surface node (index i of f.nodes), not inflated. Throws
// std::invalid_argument when a surface node has no position and std::domain_error naming the node
// when a position is not finite (the first such node). Each node on its own: `loops` may share
// them among threads.
void sweep_node_boxes(const SurfaceFeatures& f, std::span<const Vec3> x_start,
                      std::span<const Vec3> x_end, std::vector<Box>& node_boxes,
                      const ChunkedLoops& loops = serial_loops());

// The box of one feature: the hull of its nodes' boxes, inflated. feature_boxes() and the
// broad phase's cached filter both call these, so their boxes are bit-identical.
inline Box inflated(Box b, double inflation) {
  for (size_t d = 0; d < 3; ++d) {
    b.lo[d] -= inflation;
    b.hi[d] += inflation;
  }
  return b;
}

inline Box hull(Box b, const Box& o) {
  for (size_t d = 0; d < 3; ++d) {
    b.lo[d] = o.lo[d] < b.lo[d] ? o.lo[d] : b.lo[d];
    b.hi[d] = o.hi[d] > b.hi[d] ? o.hi[d] : b.hi[d];
  }
  return b;
}

inline Box edge_box(const std::array<int, 2>& e, const std::vector<Box>& node_boxes,
                    double inflation) {
  return inflated(
      hull(node_boxes[static_cast<size_t>(e[0])], node_boxes[static_cast<size_t>(e[1])]),
      inflation);
}

inline Box face_box(const std::array<int, 3>& t, const std::vector<Box>& node_boxes,
                    double inflation) {
  const Box b = hull(node_boxes[static_cast<size_t>(t[0])], node_boxes[static_cast<size_t>(t[1])]);
  return inflated(hull(b, node_boxes[static_cast<size_t>(t[2])]), inflation);
}

struct FeatureBoxes {
  std::vector<Box> node, edge, face;  // inflated; indexed like SurfaceFeatures
};

// Hulls of the given node boxes over each edge and face, then all boxes inflated (each box on
// its own: `loops` may share them among threads).
void feature_boxes(const LocalTopology& topology, const std::vector<Box>& node_boxes,
                   double inflation, FeatureBoxes& out, const ChunkedLoops& loops = serial_loops());

}  // namespace ccm::dcr
