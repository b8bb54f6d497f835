#include "engine/contact/dcr/broad_phase.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace ccm::dcr {

void BroadPhase::reset() {
  features_ = nullptr;
  stats_ = {};
}

void BroadPhase::find(const SurfaceFeatures& f, std::span<const Vec3> x_start,
                      std::span<const Vec3> x_end, double inflation, bool self_contact,
                      Candidates& out, const EdgeInflation* edges) {
  out.node_face.clear();
  out.edge_edge.clear();
  if (!(inflation >= 0) || !std::isfinite(inflation))
    throw std::invalid_argument("broad phase: inflation must be finite and >= 0, got " +
                                std::to_string(inflation));
  if (f.nodes.empty()) return;
  ++stats_.calls;
  stats_.rebuilt = !sweep_within_cache(f, x_start, x_end, inflation, self_contact);
  if (stats_.rebuilt) rebuild(f, inflation, self_contact);
  const double edge_inflation = edges ? edges->of(inflation, step_motion_) : inflation;
  stats_.step_motion = step_motion_;
  stats_.edge_inflation = edge_inflation;
  current_boxes(inflation, edge_inflation);
  filter(out);
}

// The swept node boxes of the step, and whether the cache holds for them: same surface,
// inflation and self_contact, and every node's swept box inside its allowance. A team's ranks
// each sweep their share of the nodes and agree by a maximum of their verdicts (0 the cache
// holds, 1 a rebuild, 2 a position that is not finite: every rank then sweeps every node and
// throws alike).
bool BroadPhase::sweep_within_cache(const SurfaceFeatures& f, std::span<const Vec3> x_start,
                                    std::span<const Vec3> x_end, double inflation,
                                    bool self_contact) {
  const bool same = features_ == &f && n_nodes_ == f.nodes.size() && n_edges_ == f.edges.size() &&
                    n_faces_ == f.faces.size() && inflation_ == inflation &&
                    self_contact_ == self_contact;
  node_box_.resize(f.nodes.size());
  if (team_ == nullptr) return sweep_nodes(f, x_start, x_end, 0, f.nodes.size(), same);
  const ItemShare share = share_of(team_, f.nodes.size());
  double verdict_and_motion[2] = {2.0, 0.0};  // joined in one maximum over the ranks
  try {
    verdict_and_motion[0] =
        sweep_nodes(f, x_start, x_end, share.begin, share.end, same) ? 0.0 : 1.0;
    verdict_and_motion[1] = step_motion_;
  } catch (const std::domain_error&) {
  }
  team_->max_over_ranks(verdict_and_motion);
  const double verdict = verdict_and_motion[0];
  if (verdict == 2.0) sweep_nodes(f, x_start, x_end, 0, f.nodes.size(), false);  // throws
  complete_node_boxes(f, x_start, x_end, share, verdict != 0.0);
  step_motion_ = verdict_and_motion[1];  // of every node (complete_node_boxes sweeps a part)
  return verdict == 0.0;
}

// One loop: one parallel region. Also sets step_motion_, the largest side of the boxes swept
// (a maximum: the same for any cut into chunks).
bool BroadPhase::sweep_nodes(const SurfaceFeatures& f, std::span<const Vec3> x_start,
                             std::span<const Vec3> x_end, size_t begin, size_t end, bool same) {
  const size_t n = end - begin;
  const auto chunks = static_cast<size_t>(loops_->chunks(n));
  chunk_inside_.assign(chunks, 1);
  chunk_motion_.assign(chunks, 0.0);
  loops_->run(n, [&](size_t first, size_t last, int chunk) {
    bool inside = same;  // branch-free over the chunk's nodes
    double motion = 0.0;
    for (size_t i = begin + first; i < begin + last; ++i) {
      node_box_[i] = swept_node_box(f, x_start, x_end, i);
      motion = std::max(motion, largest_side(node_box_[i]));
      if (same) inside &= contains(allowance_[i], node_box_[i]);
    }
    chunk_inside_[static_cast<size_t>(chunk)] = inside;
    chunk_motion_[static_cast<size_t>(chunk)] = motion;
  });
  step_motion_ = 0.0;
  for (double m : chunk_motion_) step_motion_ = std::max(step_motion_, m);
  return same &&
         std::all_of(chunk_inside_.begin(), chunk_inside_.end(), [](char c) { return c != 0; });
}

void BroadPhase::complete_node_boxes(const SurfaceFeatures& f, std::span<const Vec3> x_start,
                                     std::span<const Vec3> x_end, ItemShare share,
                                     bool rebuilding) {
  if (rebuilding) {
    sweep_nodes(f, x_start, x_end, 0, share.begin, false);
    sweep_nodes(f, x_start, x_end, share.end, f.nodes.size(), false);
    return;
  }
  for (int node : boxed_nodes_) {
    const auto i = static_cast<size_t>(node);
    if (i < share.begin || i >= share.end) node_box_[i] = swept_node_box(f, x_start, x_end, i);
  }
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

  feature_boxes(topology_, node_box_, 0.0, cached_, *loops_);
  const double extent = median_largest_side(cached_.face, extent_);
  const double h = std::clamp(kSkinSteps * step_motion_, kMinHalfSkinFraction * extent,
                              kHalfSkinFraction * extent);
  allowance_ = node_box_;
  for (Box& b : allowance_) {
    const double h_i = std::clamp(kSkinSteps * largest_side(b), kMinHalfSkinFraction * extent, h);
    for (size_t d = 0; d < 3; ++d) {
      b.lo[d] -= h_i;
      b.hi[d] += h_i;
    }
  }
  feature_boxes(topology_, allowance_, inflation, cached_, *loops_);
  hash_.find(f, cached_, self_contact, cache_, *loops_, team_);

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
  mark_.assign(n_nodes_, 0);
  for (int i : active_nodes_) mark_[static_cast<size_t>(i)] = 1;
  for (int e : active_edges_)
    for (int i : topology_.edges[static_cast<size_t>(e)]) mark_[static_cast<size_t>(i)] = 1;
  for (int t : active_faces_)
    for (int i : topology_.faces[static_cast<size_t>(t)]) mark_[static_cast<size_t>(i)] = 1;
  boxed_nodes_.clear();
  for (size_t i = 0; i < n_nodes_; ++i)
    if (mark_[i]) boxed_nodes_.push_back(static_cast<int>(i));
}

// The step's boxes of the active features, by the functions the grid search used (one loop over
// the active nodes, then edges, then faces).
void BroadPhase::current_boxes(double inflation, double edge_inflation) {
  current_.node.resize(n_nodes_);
  current_.edge.resize(n_edges_);
  current_.face.resize(n_faces_);
  const size_t n_nodes = active_nodes_.size(), n_edges = active_edges_.size();
  loops_->run(n_nodes + n_edges + active_faces_.size(), [&](size_t begin, size_t end, int) {
    for (size_t k = begin; k < end; ++k) {
      if (k < n_nodes) {
        const auto i = static_cast<size_t>(active_nodes_[k]);
        current_.node[i] = inflated(node_box_[i], inflation);
      } else if (k < n_nodes + n_edges) {
        const auto i = static_cast<size_t>(active_edges_[k - n_nodes]);
        current_.edge[i] = edge_box(topology_.edges[i], node_box_, edge_inflation);
      } else {
        const auto i = static_cast<size_t>(active_faces_[k - n_nodes - n_edges]);
        current_.face[i] = face_box(topology_.faces[i], node_box_, inflation);
      }
    }
  });
}

// The fresh search's test (closed box overlap) on the current boxes, over the cached pairs (one
// loop over the node-face pairs, then the edge-edge pairs; each chunk keeps its pairs in cache
// order, and the chunks are joined in order: the cache's order).
void BroadPhase::filter(Candidates& out) {
  const size_t n_nf = cache_.node_face.size(), n = n_nf + cache_.edge_edge.size();
  const int chunks = loops_->chunks(n);
  node_face_part_.reset(chunks);
  edge_edge_part_.reset(chunks);
  loops_->run(n, [&](size_t begin, size_t end, int chunk) {
    keep_overlapping(cache_.node_face, begin, std::min(end, n_nf), current_.node, current_.face,
                     &NodeFaceCandidate::node, &NodeFaceCandidate::face, node_face_part_[chunk]);
    keep_overlapping(cache_.edge_edge, std::max(begin, n_nf) - n_nf, std::max(end, n_nf) - n_nf,
                     current_.edge, current_.edge, &EdgeEdgeCandidate::edge_a,
                     &EdgeEdgeCandidate::edge_b, edge_edge_part_[chunk]);
  });
  node_face_part_.append_to(out.node_face);
  edge_edge_part_.append_to(out.edge_edge);
}

}  // namespace ccm::dcr
