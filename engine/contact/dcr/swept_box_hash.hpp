// The grid search of the DCR broad phase: every node-face and edge-edge pair of a contact surface
// whose (swept, inflated) boxes overlap (docs/contact-method.md §4).
//
// Spatial hash (Teschner et al. 2003, VMV). Every face and every edge is entered in each cell of a
// uniform grid that its box covers. Cell (i, j, k) goes to bucket H(i 73856093 ^ j 19349663 ^
// k 83492791), H being Fibonacci hashing into T = 2^bits buckets (T ~ entries / 2); the table is
// one bucket-sorted array built by counting sort (no linked lists, no per-cell allocation). Each
// node then visits the cells of its own box and tests the faces listed there, each edge the
// edges; a pair sharing a cell is reported if its boxes overlap. Two overlapping boxes always
// share the cell of the lower corner of their intersection, so nothing is missed.
//
// The cell size is the median largest extent of the face boxes, so a face covers about 1-8
// cells, and the expected cost is linear in the number of features for bounded density. A
// feature whose box would cover more than kMaxCellsPerFeature cells (a fast outlier) is kept out
// of the grid and checked against every feature of the other kind instead, so that one wild box
// cannot blow the table up.
//
// Without self-contact a feature can only pair with another body's, so a feature whose box misses
// the hull of the other bodies' partner features is neither entered nor queried: a search costs
// O(features near another body) plus one O(features) pass for the hulls.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/contact/dcr/contact_surface.hpp"
#include "engine/contact/dcr/swept_boxes.hpp"
#include "engine/contact/dcr/thread_chunks.hpp"
#include "engine/contact/replica_team.hpp"

namespace ccm::dcr {

struct NodeFaceCandidate {
  int node;  // index into SurfaceFeatures::nodes
  int face;  // index into SurfaceFeatures::faces
  friend bool operator==(const NodeFaceCandidate&, const NodeFaceCandidate&) = default;
};

struct EdgeEdgeCandidate {
  int edge_a;  // index into SurfaceFeatures::edges, edge_a < edge_b
  int edge_b;
  friend bool operator==(const EdgeEdgeCandidate&, const EdgeEdgeCandidate&) = default;
};

struct Candidates {
  std::vector<NodeFaceCandidate> node_face;  // sorted by (node, face), no duplicates
  std::vector<EdgeEdgeCandidate> edge_edge;  // sorted by (edge_a, edge_b), no duplicates
};

// Work counters of one grid search, for tests and benchmarks.
struct SearchStats {
  double cell_size = 0;
  std::size_t table_size = 0;    // buckets T
  std::size_t grid_entries = 0;  // (cell, feature) entries in the table
  std::size_t cell_visits = 0;   // cells visited by the node and edge queries
  std::size_t box_tests = 0;     // entries looked at (in the cells visited, and outliers)
  std::size_t outliers = 0;      // faces, edges and nodes tested by brute force (too many cells)
};

class SweptBoxHash {
 public:
  static constexpr std::int64_t kMaxCellsPerFeature = 4096;

  // Every pair whose boxes overlap, except a node and a face that contains it, two edges that
  // share a node, and (self_contact false) two features of the same body. `out` is overwritten;
  // the result depends only on the input. Buffers are reused (no allocation after warm-up).
  // The queries (one per node, one per edge) may be shared among threads by `loops`: each chunk
  // of queries lists its pairs in query order and the chunks are joined in order, so the list
  // is the same for any thread count; the table is built on the calling thread. With a team
  // (replica_team.hpp) each rank runs its share of the queries and the ranks join their lists:
  // the same list again; the counters of stats() are then this rank's share.
  void find(const SurfaceFeatures& f, const FeatureBoxes& boxes, bool self_contact, Candidates& out,
            const ChunkedLoops& loops = serial_loops(), const ReplicaTeam* team = nullptr);

  const SearchStats& stats() const { return stats_; }

 private:
  // What a query needs of a feature in the grid, in one cache line.
  struct FaceRecord {
    Box box;
    Triangle nodes;
    int body;
  };
  struct EdgeRecord {
    Box box;
    std::array<int, 2> nodes;
    int body;
  };
  struct CellRange {
    std::array<std::int64_t, 3> lo, hi;
  };
  // Bucket-sorted table: the entries of bucket h are entries[start[h] .. start[h + 1]).
  struct Table {
    std::vector<std::uint32_t> start;
    std::vector<int> entries;
    std::vector<int> outliers;  // features not in the grid
    int bits = 1;               // T = 2^bits buckets
  };

  // The cells a box covers; false when it covers more than kMaxCellsPerFeature cells or lies
  // too far from the origin for integer cell coordinates.
  bool cells_of(const Box& b, CellRange& r) const;
  static std::size_t bucket(std::int64_t i, std::int64_t j, std::int64_t k, int bits);
  // Enters the records with in[e] != 0.
  template <typename Record>
  void build(const std::vector<Record>& records, const std::vector<char>& in, Table& table);
  // What one chunk of queries works with: the partners of one query, and its counters (on cache
  // lines of their own: they change at every box test).
  struct alignas(kCacheLine) QueryScratch {
    std::vector<int> found;
    SearchStats stats;
  };
  // Calls test(entry) for every entry above `after` in the cells r of table t.
  template <typename Test>
  static void visit(const CellRange& r, const Table& t, int after, SearchStats& stats, Test&& test);
  void choose_grid(const FeatureBoxes& boxes);
  // node_in_, face_in_, edge_in_ and queries_ for this search.
  void select_features(const SurfaceFeatures& f, const FeatureBoxes& boxes, bool self_contact);
  // The node-face pairs of the given nodes (ascending), appended to `out` in node order.
  void find_node_face(const SurfaceFeatures& f, const FeatureBoxes& boxes, bool self_contact,
                      std::span<const std::size_t> nodes, QueryScratch& scratch,
                      std::vector<NodeFaceCandidate>& out) const;
  // The edge-edge pairs (a, b > a) of the edges a = query - n_nodes (ascending), in order of a.
  void find_edge_edge(const SurfaceFeatures& f, bool self_contact,
                      std::span<const std::size_t> queries, std::size_t n_nodes,
                      QueryScratch& scratch, std::vector<EdgeEdgeCandidate>& out) const;

  std::vector<EdgeRecord> edge_;
  std::vector<FaceRecord> face_;
  std::vector<CellRange> range_;  // scratch, per inserted feature
  // The features that may meet a partner (select_features), and the queries: the nodes, then the
  // edges as n_nodes + edge, ascending.
  std::vector<char> node_in_, face_in_, edge_in_;
  std::vector<std::size_t> queries_;
  std::vector<Box> partner_hulls_, hull_scratch_;  // scratch: per body, partner feature hulls
  std::vector<double> extent_;                     // scratch for the median
  std::vector<std::uint32_t> keys_;                // scratch: bucket of each entry
  Table faces_, edges_;
  std::vector<QueryScratch> scratch_;  // per chunk of queries
  ChunkLists<NodeFaceCandidate> node_face_part_;
  ChunkLists<EdgeEdgeCandidate> edge_edge_part_;
  std::array<double, 3> origin_{};
  double inv_cell_ = 1;
  SearchStats stats_;
};

}  // namespace ccm::dcr
