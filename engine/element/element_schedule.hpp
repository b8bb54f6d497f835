// The fixed decomposition of the element loop that lets threads share it without changing one
// bit of the result (docs/parallel.md, "Threads (OpenMP)").
//
// Each block's elements are sorted along the longest axis of the block and cut into S slabs of
// equal size, each at least kMinSlabLayers element layers thick; S depends on the mesh only, never
// on the thread count. Adjacent slabs may share
// nodes, slabs two apart may not (checked; S is halved until it holds). Phase 0 runs the even
// slabs of every block, phase 1 the odd ones: the slabs of one phase share no node, so they
// scatter into the nodal forces concurrently, and every node receives its contributions in one
// fixed order (its even slab's elements, then its odd slab's, each in slab order) whatever the
// number of threads. Inside a slab the elements keep the mesh's order, interleaved so that the
// lanes of a pack are kLaneStride elements apart (they seldom share a node).
#pragma once

#include <span>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/mesh/tet_mesh.hpp"

namespace ccm {

inline constexpr int kMinSlabElements = 512;  // a smaller slab is not worth a thread
// A slab is at least this many element layers thick along its axis: a slab one layer thick
// shares every node it writes with its neighbours, whose thread writes them in the other phase,
// and the cache lines of the nodal forces then cross between the cores at every phase: 32 slabs
// of a 32-cell cube ran two threads at 65-67 % of two, 8 slabs (4 layers) at 81-86 %
// (bench/results/two-threads-probe-2026-12-06.md).
inline constexpr double kMinSlabLayers = 4.0;
inline constexpr int kMaxSlabs = 32;    // per block: 16 per phase, balanced up to 16 threads
inline constexpr int kLaneStride = 16;  // mesh-order distance of a pack's lanes

struct Slab {
  int block = 0;
  int first_pack = 0;  // into the block's packs
  int n_packs = 0;
  int last_lanes = 0;  // lanes of the last pack that hold an element (the rest is padding)
};

struct ElementSchedule {
  std::vector<Slab> slabs;               // block by block, in slab order
  std::vector<std::vector<int>> phases;  // slab indices; the slabs of one phase share no node
};

// A block's elements [first, first + count) in kernel order, and where each slab begins in that
// order (one entry per slab plus the end).
struct BlockSlabs {
  std::vector<int> elements;
  std::vector<int> begin;
};
BlockSlabs cut_into_slabs(std::span<const Vec3> X, const std::vector<Tet>& tets, int first,
                          int count);

// Even slabs of every block, then odd ones; when the blocks share nodes (bodies never do), one
// slab per phase. slab_elements[s]: the elements of slab s.
std::vector<std::vector<int>> make_phases(int n_nodes, const std::vector<Tet>& tets,
                                          const std::vector<Slab>& slabs,
                                          const std::vector<std::span<const int>>& slab_elements);

}  // namespace ccm
