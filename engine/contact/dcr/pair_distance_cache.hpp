// The start distances of the DCR's candidate pairs kept over steps, so that a pair that stays
// apart is decided without its distance (or CCD) being computed again (docs/hard-scenes.md,
// "Resting contact").
//
// The prefilters of ccd_prefilter.hpp let a pair through unless its start distance d0 exceeds
// its nodes' reach over the step plus an allowance:
//     edge pair:  d0 > R_A + R_B + slack,               R_X the largest |x1 - x0| of side X,
//     node-face:  d0 > R_p + R_f + proximity + slack,   slack = kPrefilterSlack x edge lengths.
// Each surface node has an anchor, its start position at the last re-anchoring. A pair's
// distance d_ref, computed at start positions x_ref, bounds its distance at a later step's start
// from below: every node moved from x_ref by at most |x0 - anchor| + |x_ref - anchor| (the second
// term stored with the record), so every point of a side moved by at most the side's largest
// such sum D_X, and d0 >= d_ref - D_A - D_B (the distance of two sets is 1-Lipschitz in each).
// (The record keeps, per side, the largest |x_ref - anchor| of its nodes: D_X is bounded by the
// side's largest |x0 - anchor| plus that.) The edge lengths change by at most 2 D per edge, so the
// slack now is at most slack_ref + 6 kPrefilterSlack (D_A + D_B). Hence
//     d_ref - D_A - D_B > R_A + R_B + extra + slack_ref + 6 kPrefilterSlack (D_A + D_B) + margin
// implies the prefilter at this step would reject the pair: the pair is no contact, and nothing
// is computed for it. (margin, 1e-4 of the slack plus 1e-12 of the distances to the anchors,
// covers the rounding of the sums.) A pair the bound does not decide is tested in full, and its
// distance then becomes its new reference. When a node has moved farther than the re-anchoring
// distance from its anchor, every node is re-anchored at its start position and every record is
// dropped (the bound would weaken). The records follow the candidate lists of the broad phase
// (both sorted) from one step to the next; a pair that leaves them loses its record.
//
// The decision is the prefilter's, so the contacts found are the same as without the cache; the
// bound is per pair and reads only the positions, so the result does not depend on the threads.
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include "engine/contact/dcr/swept_box_hash.hpp"
#include "engine/core/types.hpp"

namespace ccm::dcr {

class PairDistanceCache {
 public:
  struct Record {
    // distance - (1 + 1e-4) slack at the reference start positions; -infinity: no record.
    double budget = -std::numeric_limits<double>::infinity();
    std::array<double, 2> offset{};  // per side, its nodes' largest distance to their anchors
  };

  // reanchor: the re-anchoring distance [m] (> 0).
  PairDistanceCache(std::size_t n_nodes = 0, double reanchor = 0.0)
      : anchor_(n_nodes, Vec3::Zero()), motion_(n_nodes), reanchor_(reanchor) {}

  // Before the step's tests: each node's distance to its anchor (re-anchoring all when one is
  // farther than the re-anchoring distance) and reach |x1 - x0| of the step; the records follow
  // the candidates (node-face pairs, then edge pairs; both lists sorted). nodes: the surface
  // nodes (global ids).
  void prepare(const Candidates& candidates, std::span<const int> nodes,
               const std::vector<Vec3>& x0, const std::vector<Vec3>& x1);
  // The reach of `nodes` again, after a projection moved their end positions x1 (the records
  // stay: they hold distances at start positions).
  void update_reach(std::span<const int> nodes, const std::vector<Vec3>& x0,
                    const std::vector<Vec3>& x1);
  // Whether the record of candidate k (node-face pairs first, then edge pairs) proves the pair
  // rejected by its prefilter in this step. nodes: the pair's four global ids, the first
  // `first_side` of them one side (1: node-face, 2: edge pair); extra: the proximity of a
  // node-face pair, 0 for an edge pair.
  bool proves_apart(std::size_t k, const std::array<int, 4>& nodes, int first_side,
                    double extra) const;
  // The same bound with every node's drift and reach taken at the surface's largest: weaker
  // (it implies proves_apart), but it reads no node, so it decides most pairs of a surface at
  // rest at the cost of one record.
  bool proves_apart_for_any_nodes(std::size_t k, double extra) const;
  // The start distance and slack of candidate k at this step's start positions (nodes and
  // first_side as for proves_apart).
  void record(std::size_t k, const std::array<int, 4>& nodes, int first_side, double distance,
              double slack);
  // Whether candidate k holds a record (a distance computed at this or an earlier step).
  bool has_record(std::size_t k) const {
    return records_[k].budget > -std::numeric_limits<double>::infinity();
  }
  // The candidates of the step (records held or not), and the re-anchorings so far.
  std::size_t size() const { return records_.size(); }
  long reanchorings() const { return reanchorings_; }

 private:
  std::vector<Vec3> anchor_;  // per global node
  struct Motion {
    double offset = 0.0;  // |x0 - anchor| at this step's start
    double reach = 0.0;   // |x1 - x0| of the step
  };
  std::vector<Motion> motion_;  // per global node
  Motion largest_;              // the largest offset and reach of the surface nodes
  double reanchor_ = 0.0;
  bool anchored_ = false;
  long reanchorings_ = 0;
  std::vector<NodeFaceCandidate> node_face_;
  std::vector<EdgeEdgeCandidate> edge_edge_;
  std::vector<Record> records_, previous_;  // aligned with node_face_ then edge_edge_
};

}  // namespace ccm::dcr
