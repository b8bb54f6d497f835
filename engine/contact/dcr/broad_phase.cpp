#include "engine/contact/dcr/broad_phase.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace ccm::dcr {
namespace {

// Median over the faces of the largest side of the face box.
double median_face_extent(const std::vector<Box>& faces, std::vector<double>& scratch) {
  if (faces.empty()) return 0.0;
  scratch.clear();
  for (const Box& b : faces)
    scratch.push_back(std::max({b.hi[0] - b.lo[0], b.hi[1] - b.lo[1], b.hi[2] - b.lo[2]}));
  const auto mid = scratch.begin() + static_cast<std::ptrdiff_t>(scratch.size() / 2);
  std::nth_element(scratch.begin(), mid, scratch.end());
  return *mid;
}

}  // namespace

void BroadPhase::reset() {
  features_ = nullptr;
  stats_ = {};
}

void BroadPhase::find(const SurfaceFeatures& f, std::span<const Vec3> x_start,
                      std::span<const Vec3> x_end, double inflation, bool self_contact,
                      Candidates& out) {
  out.node_face.clear();
  out.edge_edge.clear();
  if (!(inflation >= 0) || !std::isfinite(inflation))
    throw std::invalid_argument("broad phase: inflation must be finite and >= 0, got " +
                                std::to_string(inflation));
  if (f.nodes.empty()) return;
  sweep_node_boxes(f, x_start, x_end, node_box_);
  ++stats_.calls;
  stats_.rebuilt = !cache_holds(f, inflation, self_contact);
  if (stats_.rebuilt) rebuild(f, inflation, self_contact);
  current_boxes(inflation);
  filter(out);
}

// Same surface, inflation and self_contact, and every node's swept box inside its allowance.
bool BroadPhase::cache_holds(const SurfaceFeatures& f, double inflation, bool self_contact) const {
  if (features_ != &f || n_nodes_ != f.nodes.size() || n_edges_ != f.edges.size() ||
      n_faces_ != f.faces.size() || inflation_ != inflation || self_contact_ != self_contact)
    return false;
  bool inside = true;  // branch-free over all nodes
  for (size_t i = 0; i < node_box_.size(); ++i) inside &= contains(allowance_[i], node_box_[i]);
  return inside;
}

void BroadPhase::rebuild(const SurfaceFeatures& f, double inflation, bool self_contact) {
  if (features_ != &f || n_nodes_ != f.nodes.size() || n_edges_ != f.edges.size() ||
      n_faces_ != f.faces.size())
    topology_ = local_topology(f);
  features_ = &f;
  n_nodes_ = f.nodes.size();
  n_edges_ = f.edges.size();
  n_faces_ = f.faces.size();
  inflation_ = inflation;
  self_contact_ = self_contact;

  feature_boxes(topology_, node_box_, 0.0, cached_);
  const double h = kHalfSkinFraction * median_face_extent(cached_.face, extent_);
  allowance_ = node_box_;
  for (Box& b : allowance_)
    for (size_t d = 0; d < 3; ++d) {
      b.lo[d] -= h;
      b.hi[d] += h;
    }
  feature_boxes(topology_, allowance_, inflation, cached_);
  hash_.find(f, cached_, self_contact, cache_);

  static_cast<SearchStats&>(stats_) = hash_.stats();
  ++stats_.rebuilds;
  stats_.cached_pairs = cache_.node_face.size() + cache_.edge_edge.size();
  stats_.half_skin = h;
  list_active();
}

// Sorted lists of the nodes, edges and faces that occur in the cache.
void BroadPhase::list_active() {
  auto collect = [this](std::size_t n, auto&& each, std::vector<int>& out) {
    mark_.assign(n, 0);
    each([this](int i) { mark_[static_cast<size_t>(i)] = 1; });
    out.clear();
    for (size_t i = 0; i < n; ++i)
      if (mark_[i]) out.push_back(static_cast<int>(i));
  };
  collect(
      n_nodes_,
      [this](auto&& mark) {
        for (const auto& p : cache_.node_face) mark(p.node);
      },
      active_nodes_);
  collect(
      n_faces_,
      [this](auto&& mark) {
        for (const auto& p : cache_.node_face) mark(p.face);
      },
      active_faces_);
  collect(
      n_edges_,
      [this](auto&& mark) {
        for (const auto& p : cache_.edge_edge) {
          mark(p.edge_a);
          mark(p.edge_b);
        }
      },
      active_edges_);
}

// The step's boxes of the active features, by the functions the grid search used.
void BroadPhase::current_boxes(double inflation) {
  current_.node.resize(n_nodes_);
  current_.edge.resize(n_edges_);
  current_.face.resize(n_faces_);
  for (int i : active_nodes_)
    current_.node[static_cast<size_t>(i)] = inflated(node_box_[static_cast<size_t>(i)], inflation);
  for (int i : active_edges_)
    current_.edge[static_cast<size_t>(i)] =
        edge_box(topology_.edges[static_cast<size_t>(i)], node_box_, inflation);
  for (int i : active_faces_)
    current_.face[static_cast<size_t>(i)] =
        face_box(topology_.faces[static_cast<size_t>(i)], node_box_, inflation);
}

// The fresh search's test (closed box overlap) on the current boxes, over the cached pairs.
void BroadPhase::filter(Candidates& out) const {
  for (const NodeFaceCandidate& p : cache_.node_face)
    if (overlap(current_.node[static_cast<size_t>(p.node)],
                current_.face[static_cast<size_t>(p.face)]))
      out.node_face.push_back(p);
  for (const EdgeEdgeCandidate& p : cache_.edge_edge)
    if (overlap(current_.edge[static_cast<size_t>(p.edge_a)],
                current_.edge[static_cast<size_t>(p.edge_b)]))
      out.edge_edge.push_back(p);
}

}  // namespace ccm::dcr
