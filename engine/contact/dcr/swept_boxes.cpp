#include "engine/contact/dcr/swept_boxes.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace ccm::dcr {

double median_largest_side(std::span<const Box> boxes, std::vector<double>& scratch) {
  if (boxes.empty()) return 0.0;
  scratch.clear();
  for (const Box& b : boxes) scratch.push_back(largest_side(b));
  const auto mid = scratch.begin() + static_cast<std::ptrdiff_t>(scratch.size() / 2);
  std::nth_element(scratch.begin(), mid, scratch.end());
  return *mid;
}

LocalTopology local_topology(const SurfaceFeatures& f) {
  auto local = [&f](int global) {
    const auto it = std::lower_bound(f.nodes.begin(), f.nodes.end(), global);
    if (it == f.nodes.end() || *it != global)
      throw std::invalid_argument("broad phase: node " + std::to_string(global) +
                                  " of a surface feature is not a surface node");
    return static_cast<int>(it - f.nodes.begin());
  };
  LocalTopology t;
  t.faces.reserve(f.faces.size());
  for (const Triangle& face : f.faces)
    t.faces.push_back({local(face[0]), local(face[1]), local(face[2])});
  t.edges.reserve(f.edges.size());
  for (const auto& edge : f.edges) t.edges.push_back({local(edge[0]), local(edge[1])});
  return t;
}

void throw_no_position(int node) {
  throw std::invalid_argument("broad phase: surface node " + std::to_string(node) +
                              " has no position");
}

void throw_not_finite(int node) {
  throw std::domain_error("broad phase: non-finite position at node " + std::to_string(node));
}

void sweep_node_boxes(const SurfaceFeatures& f, std::span<const Vec3> x_start,
                      std::span<const Vec3> x_end, std::vector<Box>& node_boxes,
                      const ChunkedLoops& loops) {
  node_boxes.resize(f.nodes.size());
  loops.run(f.nodes.size(), [&](std::size_t begin, std::size_t end, int /*chunk*/) {
    for (size_t i = begin; i < end; ++i) node_boxes[i] = swept_node_box(f, x_start, x_end, i);
  });
}

void feature_boxes(const LocalTopology& topology, const std::vector<Box>& node_boxes,
                   double inflation, FeatureBoxes& out, const ChunkedLoops& loops) {
  out.node.resize(node_boxes.size());
  out.edge.resize(topology.edges.size());
  out.face.resize(topology.faces.size());
  // One loop over the nodes, then the edges, then the faces: item i < n_nodes is node i, and so on.
  const std::size_t n_nodes = node_boxes.size(), n_edges = topology.edges.size();
  loops.run(n_nodes + n_edges + topology.faces.size(), [&](std::size_t begin, std::size_t end,
                                                           int /*chunk*/) {
    for (size_t i = begin; i < end; ++i) {
      if (i < n_nodes)
        out.node[i] = inflated(node_boxes[i], inflation);
      else if (i < n_nodes + n_edges)
        out.edge[i - n_nodes] = edge_box(topology.edges[i - n_nodes], node_boxes, inflation);
      else
        out.face[i - n_nodes - n_edges] =
            face_box(topology.faces[i - n_nodes - n_edges], node_boxes, inflation);
    }
  });
}

}  // namespace ccm::dcr
