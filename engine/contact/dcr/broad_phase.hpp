// Broad phase of the DCR contact search: the node-face and edge-edge pairs of a contact surface
// whose swept, inflated bounding boxes overlap during a step (docs/contact-method.md §4;
// thesis 2.4).
//
// Verlet-style candidate cache with a skin (Verlet 1967; the "neighbour list" of molecular
// dynamics, here on boxes instead of spheres). At a rebuild every surface node's swept box is
// grown by a half skin h on every side into its "allowance" box, and the grid search
// (SweptBoxHash) lists every pair whose allowance-based feature boxes overlap: the cache. As long
// as every node's swept box of the current step lies inside its allowance box, every feature box
// of the step lies inside its cached counterpart (hulls and the inflation are monotone, also in
// floating point), so every pair a fresh search would report is in the cache; the step's result
// is then the cache filtered by the very box test of the fresh search, on boxes computed by the
// same function (swept_boxes.hpp): exactly the fresh result, in the same order. When a node
// leaves its allowance box (it moved about h since the rebuild), or the surface, inflation or
// self_contact changes, the cache is rebuilt from the current step's boxes.
//
// The half skin h trades rebuilds against the size of the cache, which the filter walks every
// step. Each node's covers kSkinSteps steps of its own motion in the rebuild's step, within
// [kMinHalfSkinFraction, kHalfSkinFraction] x the median largest extent of the face boxes at the
// rebuild (an eighth of an edge at most; a slow or resting node caches only the pairs within
// about 2 % of an edge), and at most kSkinSteps steps of the fastest node's motion: a crushing
// ball and the far end of the pipe it crushes keep different skins (crush family, 7 December
// 2026: 20-30 % fewer cached pairs for 2-4 % more rebuilds). h changes the work, never the
// result: the cache holds while every node stays inside its own allowance. A step then costs
// O(surface nodes) for the skin check plus O(cached pairs and their features) for the filter, with
// no hashing; a rebuild costs one grid search.
#pragma once

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

#include "engine/contact/dcr/contact_surface.hpp"
#include "engine/contact/dcr/swept_box_hash.hpp"
#include "engine/contact/dcr/swept_boxes.hpp"
#include "engine/contact/dcr/thread_chunks.hpp"
#include "engine/contact/replica_team.hpp"
#include "engine/core/types.hpp"

namespace ccm::dcr {

// An edge box's own inflation, for edge pairs that are tested for a crossing only (no proximity):
// at least max(floor, per_motion x m), m the largest side of the step's swept node boxes (how far
// the fastest surface node moved along an axis), at most the inflation of the other boxes. With
// per_motion = 2, two edges left out were more than 4 m apart over the whole step: they cannot
// cross in it, nor in the next unless the fastest node more than doubles its motion, so the step
// limit still sees an approaching pair a step before it can cross (docs/contact-time-step.md,
// "DCR"). It is the inflation halved as often as it stays above that need (a power-of-two level
// of it, exact in floating point), so it changes only when the motion crosses a level and the
// edge pairs of a slowly moving surface stay the same from step to step (the pair cache's
// records then stay in place, pair_distance_cache.hpp). The cache is built with the full
// inflation, so its pairs hold every pair of any smaller edge inflation.
struct EdgeInflation {
  double per_motion = 2.0;
  double floor = 0.0;  // [m]
  static constexpr int kMaxHalvings = 64;
  double of(double inflation, double step_motion) const {
    const double need = std::max(floor, per_motion * step_motion);
    double e = inflation;
    for (int k = 0; k < kMaxHalvings && 0.5 * e >= need; ++k) e *= 0.5;
    return e;
  }
};

// Counters of the broad phase: the grid-search counters are those of the last rebuild.
struct BroadPhaseStats : SearchStats {
  bool rebuilt = false;          // the last find() rebuilt the cache
  std::size_t rebuilds = 0;      // rebuilds since construction (or reset())
  std::size_t calls = 0;         // find() calls since construction (or reset())
  std::size_t cached_pairs = 0;  // node-face + edge-edge pairs in the cache
  double half_skin = 0;          // the largest h of the cache [m] (its fastest nodes')
  double step_motion = 0;        // m of the last find() [m] (EdgeInflation)
  double edge_inflation = 0;     // the edge boxes' inflation of the last find() [m]
};

class BroadPhase {
 public:
  // The largest h / median face extent: 0.25 until the filter lost its branches; since, the crush
  // family's members took 3-35 % less time per step at 0.125 and none more (7 December 2026).
  static constexpr double kHalfSkinFraction = 0.125;
  static constexpr double kMinHalfSkinFraction = 0.02;  // the smallest h / median face extent
  static constexpr double kSkinSteps = 200;             // steps of motion the skin covers

  // Every pair of the surface whose swept boxes [min(x_start, x_end) - inflation,
  // max(x_start, x_end) + inflation] overlap (closed intervals; an edge's box inflated by
  // `edges` when given), except:
  //  - a node and a face that contains it, and two edges that share a node;
  //  - when self_contact is false, any two features of the same body.
  // x_start and x_end are positions indexed by global node id (the whole model's x_n and
  // x_{n+1}). `out` is overwritten. The result depends only on the input (never on hash order,
  // on the cache or on what this object did before). The cache is keyed on the address and the
  // sizes of `f`: call reset() after editing a SurfaceFeatures in place. Buffers are reused, so
  // after warm-up a step allocates nothing (reuse `out` as well).
  // Throws std::domain_error naming the node when a surface position is not finite.
  // edges: the edge boxes' own inflation (EdgeInflation); without it they take `inflation`.
  void find(const SurfaceFeatures& f, std::span<const Vec3> x_start, std::span<const Vec3> x_end,
            double inflation, bool self_contact, Candidates& out,
            const EdgeInflation* edges = nullptr);

  // Forgets the cache (the next find() rebuilds).
  void reset();

  // The loops find() may share among threads (the result is the same; default: one thread).
  // `loops` must outlive this object's calls to find().
  void use_loops(const ChunkedLoops& loops) { loops_ = &loops; }

  // A partitioned run's team (replica_team.hpp): the sweep over the surface nodes is split among
  // its ranks (the result is the same). `team` must outlive this object's calls to find().
  void use_team(const ReplicaTeam& team) { team_ = &team; }

  const BroadPhaseStats& stats() const { return stats_; }

 private:
  bool sweep_within_cache(const SurfaceFeatures& f, std::span<const Vec3> x_start,
                          std::span<const Vec3> x_end, double inflation, bool self_contact);
  // The swept boxes of the nodes [begin, end); whether all lie in their allowance (if same).
  bool sweep_nodes(const SurfaceFeatures& f, std::span<const Vec3> x_start,
                   std::span<const Vec3> x_end, std::size_t begin, std::size_t end, bool same);
  // The swept boxes beyond this rank's share that the step reads: every node's for a rebuild,
  // else those of boxed_nodes_.
  void complete_node_boxes(const SurfaceFeatures& f, std::span<const Vec3> x_start,
                           std::span<const Vec3> x_end, ItemShare share, bool rebuilding);
  void rebuild(const SurfaceFeatures& f, double inflation, bool self_contact);
  void list_active();
  void current_boxes(double inflation, double edge_inflation);
  void filter(Candidates& out);
  // The pairs [begin, end) of `pairs` whose two boxes (a_boxes[pair.*a], b_boxes[pair.*b])
  // overlap, appended to `kept` in order. Branch-free: every pair is written and the end moves
  // on by the test's outcome (about one pair in ten overlaps, which a branch mispredicts).
  template <class Pair>
  static void keep_overlapping(const std::vector<Pair>& pairs, size_t begin, size_t end,
                               const std::vector<Box>& a_boxes, const std::vector<Box>& b_boxes,
                               int Pair::*a, int Pair::*b, std::vector<Pair>& kept) {
    if (begin >= end) return;
    size_t n = kept.size();
    kept.resize(n + (end - begin));
    for (size_t k = begin; k < end; ++k) {
      const Pair& p = pairs[k];
      kept[n] = p;
      n += overlap_branchless(a_boxes[static_cast<size_t>(p.*a)],
                              b_boxes[static_cast<size_t>(p.*b)]);
    }
    kept.resize(n);
  }

  // What the cache was built for.
  const SurfaceFeatures* features_ = nullptr;
  std::size_t n_nodes_ = 0, n_edges_ = 0, n_faces_ = 0;
  double inflation_ = 0;
  bool self_contact_ = false;

  LocalTopology topology_;
  std::vector<Box> node_box_;   // swept node boxes of the current step
  std::vector<Box> allowance_;  // node boxes of the last rebuild grown by the half skin
  FeatureBoxes current_;        // feature boxes of the current step (of the active features)
  FeatureBoxes cached_;         // feature boxes of the allowance (scratch of rebuild)
  // The features that occur in the cache: only their boxes are needed at a step.
  std::vector<int> active_nodes_, active_edges_, active_faces_;
  std::vector<int> boxed_nodes_;  // the nodes whose boxes the active features read, sorted
  std::vector<char> mark_;        // scratch
  std::vector<double> extent_;    // scratch for the median
  Candidates cache_;
  SweptBoxHash hash_;
  const ChunkedLoops* loops_ = &serial_loops();
  const ReplicaTeam* team_ = nullptr;
  std::vector<char> chunk_inside_;                // scratch of sweep_within_cache, per chunk
  std::vector<double> chunk_motion_;              // ... and the largest side of its node boxes
  double step_motion_ = 0;                        // m of the step (all nodes, all ranks)
  ChunkLists<NodeFaceCandidate> node_face_part_;  // scratch of filter, per chunk
  ChunkLists<EdgeEdgeCandidate> edge_edge_part_;
  BroadPhaseStats stats_;
};

}  // namespace ccm::dcr
