#include "engine/contact/dcr/pair_distance_cache.hpp"

#include <algorithm>
#include <tuple>

#include "engine/contact/dcr/ccd_prefilter.hpp"

namespace ccm::dcr {
namespace {

bool pdc_before(const NodeFaceCandidate& a, const NodeFaceCandidate& b) {
  return std::tie(a.node, a.face) < std::tie(b.node, b.face);
}
bool pdc_before(const EdgeEdgeCandidate& a, const EdgeEdgeCandidate& b) {
  return std::tie(a.edge_a, a.edge_b) < std::tie(b.edge_a, b.edge_b);
}

// The records of `now` (sorted) taken from those of `before` (sorted, records from `from`),
// written from `to`: a merge of the two lists.
template <typename Pair>
void pdc_carry(const std::vector<Pair>& before, const std::vector<PairDistanceCache::Record>& old,
               std::size_t from, const std::vector<Pair>& now,
               std::vector<PairDistanceCache::Record>& out, std::size_t to) {
  std::size_t i = 0;
  for (std::size_t k = 0; k < now.size(); ++k) {
    while (i < before.size() && pdc_before(before[i], now[k])) ++i;
    out[to + k] =
        i < before.size() && before[i] == now[k] ? old[from + i] : PairDistanceCache::Record{};
  }
}

// The bound of the header for a record: its budget, less the sides' drifts D_A + D_B with the
// slack's growth and the rounding margin on them, exceeds the sides' reach plus `extra`.
bool pdc_clears(const PairDistanceCache::Record& r, double drifts, double reaches, double extra) {
  return r.budget - (1.0 + 6.0 * kPrefilterSlack + 1e-12) * drifts > reaches + extra;
}

}  // namespace

void PairDistanceCache::prepare(const Candidates& candidates, std::span<const int> nodes,
                                const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
  bool reanchor = !anchored_;
  largest_ = {};
  for (int n : nodes) {
    const auto i = static_cast<std::size_t>(n);
    motion_[i].reach = (x1[i] - x0[i]).norm();
    motion_[i].offset = (x0[i] - anchor_[i]).norm();
    reanchor = reanchor || !(motion_[i].offset <= reanchor_);
    largest_.reach = std::max(largest_.reach, motion_[i].reach);
    largest_.offset = std::max(largest_.offset, motion_[i].offset);
  }
  // The same candidates as in the last step (a surface at rest between two broad-phase changes):
  // every record stays where it is.
  const bool same =
      !reanchor && candidates.node_face == node_face_ && candidates.edge_edge == edge_edge_;
  if (same) return;
  std::swap(records_, previous_);
  records_.resize(candidates.node_face.size() + candidates.edge_edge.size());
  if (reanchor) {
    for (int n : nodes) {
      const auto i = static_cast<std::size_t>(n);
      anchor_[i] = x0[i];
      motion_[i].offset = 0.0;
    }
    largest_.offset = 0.0;
    anchored_ = true;
    ++reanchorings_;
    std::fill(records_.begin(), records_.end(), Record{});
  } else {
    pdc_carry(node_face_, previous_, 0, candidates.node_face, records_, 0);
    pdc_carry(edge_edge_, previous_, node_face_.size(), candidates.edge_edge, records_,
              candidates.node_face.size());
  }
  node_face_ = candidates.node_face;
  edge_edge_ = candidates.edge_edge;
}

void PairDistanceCache::update_reach(std::span<const int> nodes, const std::vector<Vec3>& x0,
                                     const std::vector<Vec3>& x1) {
  for (int n : nodes) {
    const auto i = static_cast<std::size_t>(n);
    motion_[i].reach = (x1[i] - x0[i]).norm();
    largest_.reach = std::max(largest_.reach, motion_[i].reach);  // still a bound of all
  }
}

bool PairDistanceCache::proves_apart_for_any_nodes(std::size_t k, double extra) const {
  const Record& r = records_[k];
  return pdc_clears(r, 2.0 * largest_.offset + r.offset[0] + r.offset[1], 2.0 * largest_.reach,
                    extra);
}

bool PairDistanceCache::proves_apart(std::size_t k, const std::array<int, 4>& nodes, int first_side,
                                     double extra) const {
  const Record& r = records_[k];
  double drift[2] = {0.0, 0.0}, reach[2] = {0.0, 0.0};
  for (int j = 0; j < 4; ++j) {
    const Motion& m = motion_[static_cast<std::size_t>(nodes[static_cast<std::size_t>(j)])];
    const int side = j < first_side ? 0 : 1;
    drift[side] = std::max(drift[side], m.offset);
    reach[side] = std::max(reach[side], m.reach);
  }
  return pdc_clears(r, drift[0] + r.offset[0] + drift[1] + r.offset[1], reach[0] + reach[1], extra);
}

void PairDistanceCache::record(std::size_t k, const std::array<int, 4>& nodes, int first_side,
                               double distance, double slack) {
  Record& r = records_[k];
  r.budget = distance - (1.0 + 1e-4) * slack;
  r.offset = {0.0, 0.0};
  for (int j = 0; j < 4; ++j) {
    const int side = j < first_side ? 0 : 1;
    r.offset[static_cast<std::size_t>(side)] =
        std::max(r.offset[static_cast<std::size_t>(side)],
                 motion_[static_cast<std::size_t>(nodes[static_cast<std::size_t>(j)])].offset);
  }
}

}  // namespace ccm::dcr
