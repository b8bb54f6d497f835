// Broad phase of the DCR contact search: the node-face and edge-edge pairs of a contact surface
// whose swept bounding boxes overlap during a step (contact-method.md §4).
//
// Spatial hash (Teschner et al. 2003, VMV). Every face and every edge is entered in each cell of a
// uniform grid that its swept box [min(x_start, x_end) - inflation, max(x_start, x_end) +
// inflation] covers. Cell (i, j, k) goes to bucket H(i 73856093 ^ j 19349663 ^ k 83492791), H
// being Fibonacci hashing into T = 2^bits buckets (T ~ entries / 2); the table is one
// bucket-sorted array built by counting sort (no linked lists, no per-cell allocation). Each node
// then visits the cells of its own swept box and tests the faces listed there, each edge the
// edges; a pair sharing a cell is reported if its boxes overlap. Two overlapping boxes always
// share the cell of the lower corner of their intersection, so nothing is missed.
//
// The cell size is the median largest extent of the faces' swept boxes, so a face covers about
// 1-8 cells, and the expected cost is linear in the number of features for bounded density.
// A feature whose box would cover more than kMaxCellsPerFeature cells (a fast outlier) is kept out
// of the grid and checked against every feature of the other kind instead, so that one wild box
// cannot blow the table up.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/contact/dcr/contact_surface.hpp"
#include "engine/core/types.hpp"

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

// Work counters of the last find(), for tests and benchmarks.
struct BroadPhaseStats {
  double cell_size = 0;
  std::size_t table_size = 0;    // buckets T
  std::size_t grid_entries = 0;  // (cell, feature) entries in the table
  std::size_t cell_visits = 0;   // cells visited by the node and edge queries
  std::size_t box_tests = 0;     // entries looked at (in the cells visited, and outliers)
  std::size_t outliers = 0;      // faces, edges and nodes tested by brute force (too many cells)
};

class BroadPhase {
 public:
  static constexpr std::int64_t kMaxCellsPerFeature = 4096;

  // Every pair of the surface whose swept boxes overlap (closed intervals), except:
  //  - a node and a face that contains it, and two edges that share a node;
  //  - when self_contact is false, any two features of the same body.
  // x_start and x_end are positions indexed by global node id (the whole model's x_n and x_{n+1}).
  // `out` is overwritten. The result depends only on the input (never on hash order or on what
  // this object did before). Buffers are reused, so after warm-up a step allocates nothing
  // (reuse `out` as well).
  // Throws std::domain_error naming the node when a surface position is not finite.
  void find(const SurfaceFeatures& f, std::span<const Vec3> x_start, std::span<const Vec3> x_end,
            double inflation, bool self_contact, Candidates& out);

  const BroadPhaseStats& stats() const { return stats_; }

 private:
  struct Box {
    std::array<double, 3> lo, hi;
  };
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
  template <typename Record>
  void build(const std::vector<Record>& records, Table& table);

  std::vector<Box> node_box_;
  std::vector<EdgeRecord> edge_;
  std::vector<FaceRecord> face_;
  std::vector<CellRange> range_;     // scratch, per inserted feature
  std::vector<double> extent_;       // scratch for the median
  std::vector<std::uint32_t> keys_;  // scratch: bucket of each entry
  Table faces_, edges_;
  std::vector<int> found_;  // scratch: the partners of one query
  std::array<double, 3> origin_{};
  double inv_cell_ = 1;
  BroadPhaseStats stats_;
};

}  // namespace ccm::dcr
