#include "engine/contact/dcr/swept_box_hash.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace ccm::dcr {
namespace {

// Cell coordinates beyond this magnitude are not representable exactly; such boxes are outliers.
constexpr double kMaxCellCoordinate = 4.5e15;  // ~2^52

bool shares_node(const std::array<int, 2>& e, const std::array<int, 2>& g) {
  return e[0] == g[0] || e[0] == g[1] || e[1] == g[0] || e[1] == g[1];
}

Box empty_box() {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  return {{kInf, kInf, kInf}, {-kInf, -kInf, -kInf}};  // overlaps nothing
}

// Up to this many bodies a feature is tested against each other body's hull; beyond it, against
// the hull of all other bodies together (one test per feature instead of one per body).
constexpr size_t kMaxSeparateHulls = 8;

// Per body b, the hull of b's features, or (n_bodies > kMaxSeparateHulls) of every other body's.
const std::vector<Box>& partner_hulls(const std::vector<int>& body, const std::vector<Box>& boxes,
                                      size_t n_bodies, std::vector<Box>& hulls,
                                      std::vector<Box>& scratch) {
  hulls.assign(n_bodies, empty_box());
  for (size_t i = 0; i < boxes.size(); ++i) {
    Box& h = hulls[static_cast<size_t>(body[i])];
    h = hull(h, boxes[i]);
  }
  if (n_bodies <= kMaxSeparateHulls) return hulls;
  scratch.assign(n_bodies + 1, empty_box());  // scratch[b]: the hull of bodies b, b + 1, ...
  for (size_t b = n_bodies; b-- > 0;) scratch[b] = hull(scratch[b + 1], hulls[b]);
  Box before = empty_box();  // the hull of bodies 0 .. b - 1
  for (size_t b = 0; b < n_bodies; ++b) {
    const Box own = hulls[b];
    hulls[b] = hull(before, scratch[b + 1]);
    before = hull(before, own);
  }
  return hulls;
}

// in[i]: whether feature i (of body body[i]) may meet a partner, i.e. its box overlaps the hull
// of another body's partner features (or, joined, the hull of all other bodies').
void mark_reachable(const std::vector<int>& body, const std::vector<Box>& boxes,
                    const std::vector<Box>& hulls, std::vector<char>& in) {
  in.resize(boxes.size());
  const bool joined = hulls.size() > kMaxSeparateHulls;  // hulls[b]: every body but b
  for (size_t i = 0; i < boxes.size(); ++i) {
    const auto own = static_cast<size_t>(body[i]);
    if (joined) {
      in[i] = overlap(boxes[i], hulls[own]);
      continue;
    }
    bool reachable = false;
    for (size_t c = 0; c < hulls.size() && !reachable; ++c)
      reachable = c != own && overlap(boxes[i], hulls[c]);
    in[i] = reachable;
  }
}

size_t count_bodies(const SurfaceFeatures& f) {
  int last = -1;
  for (const std::vector<int>* body : {&f.node_body, &f.edge_body, &f.face_body})
    for (int b : *body) last = std::max(last, b);
  return static_cast<size_t>(last + 1);
}

void sort_unique(std::vector<int>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

// The candidates of every rank's share of the queries, joined in rank order: each rank's
// node-face pairs come from a run of node queries and its edge-edge pairs from a run of edge
// queries, so the ranks' lists joined in order are the lists of all queries in order. A rank's
// part travels as (node-face count, edge-edge count, the pairs).
void join_candidates_over_ranks(const ReplicaTeam& team, Candidates& out) {
  std::vector<int> mine = {static_cast<int>(out.node_face.size()),
                           static_cast<int>(out.edge_edge.size())};
  for (const NodeFaceCandidate& c : out.node_face) mine.insert(mine.end(), {c.node, c.face});
  for (const EdgeEdgeCandidate& c : out.edge_edge) mine.insert(mine.end(), {c.edge_a, c.edge_b});
  const std::vector<int> all = team.join_over_ranks(mine);
  out.node_face.clear();
  out.edge_edge.clear();
  for (size_t k = 0; k < all.size();) {
    const auto n_nf = static_cast<size_t>(all[k]), n_ee = static_cast<size_t>(all[k + 1]);
    k += 2;
    for (size_t j = 0; j < n_nf; ++j, k += 2) out.node_face.push_back({all[k], all[k + 1]});
    for (size_t j = 0; j < n_ee; ++j, k += 2) out.edge_edge.push_back({all[k], all[k + 1]});
  }
}

}  // namespace

bool SweptBoxHash::cells_of(const Box& b, CellRange& r) const {
  std::int64_t count = 1;
  for (size_t d = 0; d < 3; ++d) {
    const double lo = std::floor((b.lo[d] - origin_[d]) * inv_cell_);
    const double hi = std::floor((b.hi[d] - origin_[d]) * inv_cell_);
    if (!(std::abs(lo) < kMaxCellCoordinate && std::abs(hi) < kMaxCellCoordinate)) return false;
    if (hi - lo >= static_cast<double>(kMaxCellsPerFeature)) return false;
    r.lo[d] = static_cast<std::int64_t>(lo);
    r.hi[d] = static_cast<std::int64_t>(hi);
    count *= r.hi[d] - r.lo[d] + 1;
    if (count > kMaxCellsPerFeature) return false;
  }
  return true;
}

std::size_t SweptBoxHash::bucket(std::int64_t i, std::int64_t j, std::int64_t k, int bits) {
  // Teschner et al. 2003, then Fibonacci hashing to spread the XOR over the top `bits` bits.
  const std::uint64_t h = (static_cast<std::uint64_t>(i) * 73856093u) ^
                          (static_cast<std::uint64_t>(j) * 19349663u) ^
                          (static_cast<std::uint64_t>(k) * 83492791u);
  return static_cast<std::size_t>((h * 0x9E3779B97F4A7C15ull) >> (64 - bits));
}

template <typename Record>
void SweptBoxHash::build(const std::vector<Record>& records, const std::vector<char>& in,
                         Table& table) {
  // Pass 1: cell ranges and the number of entries.
  range_.resize(records.size());
  table.outliers.clear();
  std::size_t n_entries = 0;
  for (size_t e = 0; e < records.size(); ++e) {
    CellRange& r = range_[e];
    if (!in[e]) {
      r.lo[0] = 1;  // empty range: not in the grid
      r.hi[0] = 0;
      continue;
    }
    if (!cells_of(records[e].box, r)) {
      table.outliers.push_back(static_cast<int>(e));
      r.lo[0] = 1;  // empty range: not in the grid
      r.hi[0] = 0;
      continue;
    }
    n_entries += static_cast<std::size_t>((r.hi[0] - r.lo[0] + 1) * (r.hi[1] - r.lo[1] + 1) *
                                          (r.hi[2] - r.lo[2] + 1));
  }
  // A cell holds ~10 entries on a surface, so n_entries / 2 buckets keep collisions rare while
  // the table stays small enough for the cache.
  if (n_entries >= std::size_t{1} << 31)
    throw std::length_error("broad phase: too many grid entries (" + std::to_string(n_entries) +
                            ")");
  table.bits = 4;
  while ((std::size_t{1} << table.bits) < n_entries / 2) ++table.bits;
  const std::size_t n_buckets = std::size_t{1} << table.bits;

  // Pass 2: the bucket of every (feature, cell) entry, counted per bucket.
  keys_.clear();
  table.start.assign(n_buckets + 1, 0);
  for (size_t e = 0; e < records.size(); ++e) {
    const CellRange& r = range_[e];
    if (r.lo[0] > r.hi[0]) continue;
    for (std::int64_t k = r.lo[2]; k <= r.hi[2]; ++k)
      for (std::int64_t j = r.lo[1]; j <= r.hi[1]; ++j)
        for (std::int64_t i = r.lo[0]; i <= r.hi[0]; ++i) {
          const std::uint32_t h = static_cast<std::uint32_t>(bucket(i, j, k, table.bits));
          keys_.push_back(h);
          ++table.start[h];
        }
  }
  // Inclusive prefix sum: start[h] = end of bucket h; then filling backwards leaves start[h] at
  // the beginning of bucket h, and start[T] = number of entries.
  for (size_t h = 0; h < n_buckets; ++h) table.start[h + 1] += table.start[h];
  table.entries.resize(n_entries);
  std::size_t key = n_entries;
  for (size_t e = records.size(); e-- > 0;) {
    const CellRange& r = range_[e];
    if (r.lo[0] > r.hi[0]) continue;
    const std::size_t n_cells = static_cast<std::size_t>(
        (r.hi[0] - r.lo[0] + 1) * (r.hi[1] - r.lo[1] + 1) * (r.hi[2] - r.lo[2] + 1));
    for (size_t c = 0; c < n_cells; ++c) {
      const std::uint32_t h = keys_[--key];
      table.entries[--table.start[h]] = static_cast<int>(e);
    }
  }
  stats_.grid_entries += n_entries;
  stats_.table_size += n_buckets;
  stats_.outliers += table.outliers.size();
}

// A bucket lists its entries in ascending order (build() fills it backwards), so it is read from
// the top down to the first entry <= after.
template <typename Test>
void SweptBoxHash::visit(const CellRange& r, const Table& t, int after, SearchStats& stats,
                         Test&& test) {
  for (std::int64_t k = r.lo[2]; k <= r.hi[2]; ++k)
    for (std::int64_t j = r.lo[1]; j <= r.hi[1]; ++j)
      for (std::int64_t i = r.lo[0]; i <= r.hi[0]; ++i) {
        const std::size_t h = bucket(i, j, k, t.bits);
        const std::uint32_t begin = t.start[h];
        ++stats.cell_visits;
        for (std::uint32_t e = t.start[h + 1]; e > begin;) {
          const int entry = t.entries[--e];
          if (entry <= after) break;
          ++stats.box_tests;
          test(entry);
        }
      }
}

// Grid origin at the lowest face corner, cell = median largest extent of the face boxes.
void SweptBoxHash::choose_grid(const FeatureBoxes& boxes) {
  origin_ = boxes.face.empty() ? boxes.node[0].lo : boxes.face[0].lo;
  double largest = 0;
  for (const Box& b : boxes.face) {
    for (size_t d = 0; d < 3; ++d) origin_[d] = std::min(origin_[d], b.lo[d]);
    largest = std::max(largest, largest_side(b));
  }
  double cell = median_largest_side(boxes.face, extent_);
  if (!(cell > 0)) cell = largest;
  if (!(cell > 0)) cell = 1;  // every face is a point: any cell size works
  inv_cell_ = 1.0 / cell;
  stats_.cell_size = cell;
}

// Without self-contact a feature pairs only with features of other bodies, so a feature whose
// box misses the hull of each other body's partner features (faces for a node, nodes for a face,
// edges for an edge) can pair with nothing: it is neither entered in the grid nor queried. The list
// is unchanged; the work shrinks to the features near another body.
void SweptBoxHash::select_features(const SurfaceFeatures& f, const FeatureBoxes& boxes,
                                   bool self_contact) {
  if (self_contact) {  // every feature may meet another of its own body
    node_in_.assign(f.nodes.size(), 1);
    face_in_.assign(f.faces.size(), 1);
    edge_in_.assign(f.edges.size(), 1);
  } else {
    const size_t n_bodies = count_bodies(f);
    mark_reachable(f.node_body, boxes.node,
                   partner_hulls(f.face_body, boxes.face, n_bodies, partner_hulls_, hull_scratch_),
                   node_in_);
    mark_reachable(f.face_body, boxes.face,
                   partner_hulls(f.node_body, boxes.node, n_bodies, partner_hulls_, hull_scratch_),
                   face_in_);
    mark_reachable(f.edge_body, boxes.edge,
                   partner_hulls(f.edge_body, boxes.edge, n_bodies, partner_hulls_, hull_scratch_),
                   edge_in_);
  }
  queries_.clear();  // the nodes, then the edges (as n_nodes + edge)
  for (size_t i = 0; i < node_in_.size(); ++i)
    if (node_in_[i]) queries_.push_back(i);
  for (size_t a = 0; a < edge_in_.size(); ++a)
    if (edge_in_[a]) queries_.push_back(node_in_.size() + a);
}

void SweptBoxHash::find(const SurfaceFeatures& f, const FeatureBoxes& boxes, bool self_contact,
                        Candidates& out, const ChunkedLoops& loops, const ReplicaTeam* team) {
  out.node_face.clear();
  out.edge_edge.clear();
  stats_ = {};
  if (f.nodes.empty()) return;
  edge_.resize(f.edges.size());
  for (size_t i = 0; i < f.edges.size(); ++i)
    edge_[i] = {boxes.edge[i], f.edges[i], f.edge_body[i]};
  face_.resize(f.faces.size());
  for (size_t i = 0; i < f.faces.size(); ++i)
    face_[i] = {boxes.face[i], f.faces[i], f.face_body[i]};
  choose_grid(boxes);
  select_features(f, boxes, self_contact);
  build(face_, face_in_, faces_);
  build(edge_, edge_in_, edges_);
  // One loop over the queries: the nodes (against the faces), then the edges (against the edges).
  const size_t n_nodes = f.nodes.size();
  const ItemShare share = share_of(team, queries_.size());
  const size_t n = share.end - share.begin;
  const int chunks = loops.chunks(n, ChunkedLoops::kHeavyItem);
  scratch_.resize(std::max(scratch_.size(), static_cast<size_t>(chunks)));
  node_face_part_.reset(chunks);
  edge_edge_part_.reset(chunks);
  loops.run(
      n,
      [&](size_t first, size_t last, int chunk) {
        const auto begin = queries_.begin() + static_cast<std::ptrdiff_t>(share.begin + first);
        const auto end = queries_.begin() + static_cast<std::ptrdiff_t>(share.begin + last);
        const auto edges = std::lower_bound(begin, end, n_nodes);
        QueryScratch& scratch = scratch_[static_cast<size_t>(chunk)];
        scratch.stats = {};
        find_node_face(f, boxes, self_contact, {begin, edges}, scratch, node_face_part_[chunk]);
        find_edge_edge(f, self_contact, {edges, end}, n_nodes, scratch, edge_edge_part_[chunk]);
      },
      ChunkedLoops::kHeavyItem);
  node_face_part_.append_to(out.node_face);
  edge_edge_part_.append_to(out.edge_edge);
  if (team) join_candidates_over_ranks(*team, out);
  for (int c = 0; c < chunks; ++c) {  // integer counters: the sum does not depend on the order
    const SearchStats& s = scratch_[static_cast<size_t>(c)].stats;
    stats_.cell_visits += s.cell_visits;
    stats_.box_tests += s.box_tests;
    stats_.outliers += s.outliers;
  }
}

void SweptBoxHash::find_node_face(const SurfaceFeatures& f, const FeatureBoxes& boxes,
                                  bool self_contact, std::span<const size_t> nodes,
                                  QueryScratch& scratch,
                                  std::vector<NodeFaceCandidate>& out) const {
  CellRange cells;
  std::vector<int>& found = scratch.found;
  SearchStats& stats = scratch.stats;
  for (size_t i : nodes) {
    const int node = f.nodes[i];
    const int body = self_contact ? -1 : f.node_body[i];
    const Box& q = boxes.node[i];
    found.clear();
    auto test = [&](int face) {
      const FaceRecord& rec = face_[static_cast<size_t>(face)];
      if (!overlap(q, rec.box) || rec.body == body) return;
      if (rec.nodes[0] == node || rec.nodes[1] == node || rec.nodes[2] == node) return;
      found.push_back(face);
    };
    if (cells_of(q, cells)) {
      visit(cells, faces_, -1, stats, test);
      for (int face : faces_.outliers) test(face);
      stats.box_tests += faces_.outliers.size();
    } else {
      ++stats.outliers;
      for (int face = 0; face < f.n_faces(); ++face) test(face);
      stats.box_tests += f.faces.size();
    }
    sort_unique(found);
    for (int face : found) out.push_back({static_cast<int>(i), face});
  }
}

// Each pair (a, b) once, with a < b.
void SweptBoxHash::find_edge_edge(const SurfaceFeatures& f, bool self_contact,
                                  std::span<const size_t> queries, size_t n_nodes,
                                  QueryScratch& scratch,
                                  std::vector<EdgeEdgeCandidate>& out) const {
  CellRange cells;
  std::vector<int>& found = scratch.found;
  SearchStats& stats = scratch.stats;
  for (size_t query : queries) {
    const size_t a = query - n_nodes;
    const std::array<int, 2> ea = f.edges[a];
    const int body = self_contact ? -1 : f.edge_body[a];
    const int ia = static_cast<int>(a);
    const Box& q = edge_[a].box;
    found.clear();
    auto test = [&](int b) {  // b > ia
      const EdgeRecord& rec = edge_[static_cast<size_t>(b)];
      if (!overlap(q, rec.box) || rec.body == body) return;
      if (shares_node(ea, rec.nodes)) return;
      found.push_back(b);
    };
    if (cells_of(q, cells)) {
      visit(cells, edges_, ia, stats, test);
      for (int b : edges_.outliers)
        if (b > ia) test(b);
      stats.box_tests += edges_.outliers.size();
    } else {
      for (int b = ia + 1; b < f.n_edges(); ++b) test(b);
      stats.box_tests += f.edges.size() - a - 1;
    }
    sort_unique(found);
    for (int b : found) out.push_back({ia, b});
  }
}

}  // namespace ccm::dcr
