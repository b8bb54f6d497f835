#include "engine/element/element_schedule.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "engine/element/element_pack.hpp"

namespace ccm {
namespace {

// Index (0, 1, 2) of the longest side of the bounding box of the block's nodes.
int longest_axis(std::span<const Vec3> X, const std::vector<Tet>& tets, int first, int count) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (int e = first; e < first + count; ++e)
    for (int n : tets[static_cast<size_t>(e)]) {
      lo = lo.cwiseMin(X[static_cast<size_t>(n)]);
      hi = hi.cwiseMax(X[static_cast<size_t>(n)]);
    }
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  return axis;
}

// Whether slabs two or more apart share no node: every node's slabs are one or two adjacent.
bool slabs_separated(const std::vector<Tet>& tets, const BlockSlabs& s, size_t n_nodes) {
  std::vector<int> lowest(n_nodes, -1), highest(n_nodes, -1);
  for (size_t k = 0; k + 1 < s.begin.size(); ++k)
    for (int i = s.begin[k]; i < s.begin[k + 1]; ++i)
      for (int n : tets[static_cast<size_t>(s.elements[static_cast<size_t>(i)])]) {
        const auto j = static_cast<size_t>(n);
        if (lowest[j] < 0) lowest[j] = static_cast<int>(k);
        highest[j] = static_cast<int>(k);
      }
  for (size_t j = 0; j < n_nodes; ++j)
    if (highest[j] - lowest[j] > 1) return false;
  return true;
}

// Interleaves each full group of kLanes x kLaneStride elements so that lane l of the group's
// pack k holds its element l kLaneStride + k: the lanes of a pack are elements kLaneStride apart
// in the mesh order, which rarely share a node, so the scatter's read-modify-writes of one pack
// do not wait on each other; each lane still walks through the mesh in order.
void interleave_lanes(std::span<int> elements) {
  constexpr int kGroup = kLanes * kLaneStride;
  std::vector<int> group(kGroup);
  for (size_t g = 0; g + kGroup <= elements.size(); g += kGroup) {
    std::copy_n(elements.begin() + static_cast<long>(g), kGroup, group.begin());
    for (int k = 0; k < kLaneStride; ++k)
      for (int l = 0; l < kLanes; ++l)
        elements[g + static_cast<size_t>(k * kLanes + l)] =
            group[static_cast<size_t>(l * kLaneStride + k)];
  }
}

// How many slabs of kMinSlabLayers element layers fit in `extent` (the span of the element
// centres along the slab axis). An element layer is the edge of a cube of six mean tets,
// (6 V_mean)^(1/3): one cell of a structured mesh.
int slabs_by_thickness(double extent, std::span<const Vec3> X, const std::vector<Tet>& tets,
                       int first, int count) {
  double volume = 0.0;
  for (int i = first; i < first + count; ++i) {
    const Tet& t = tets[static_cast<size_t>(i)];
    const Vec3& a = X[static_cast<size_t>(t[0])];
    volume +=
        std::abs(
            (X[static_cast<size_t>(t[1])] - a)
                .dot((X[static_cast<size_t>(t[2])] - a).cross(X[static_cast<size_t>(t[3])] - a))) /
        6.0;
  }
  const double layer = std::cbrt(6.0 * volume / count);
  if (!(layer > 0.0)) return kMaxSlabs;
  // The centres span (cells - 1) layers: one layer is added back.
  return static_cast<int>(std::floor((extent + layer) / (kMinSlabLayers * layer)));
}

}  // namespace

BlockSlabs cut_into_slabs(std::span<const Vec3> X, const std::vector<Tet>& tets, int first,
                          int count) {
  std::vector<int> sorted(static_cast<size_t>(count));
  std::iota(sorted.begin(), sorted.end(), first);
  int most_slabs = kMaxSlabs;
  if (count > 0) {
    const int axis = longest_axis(X, tets, first, count);
    std::vector<double> key(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) {
      const Tet& t = tets[static_cast<size_t>(first + i)];
      double c = 0.0;
      for (int n : t) c += X[static_cast<size_t>(n)][axis];
      key[static_cast<size_t>(i)] = c;
    }
    std::stable_sort(sorted.begin(), sorted.end(), [&](int a, int b) {
      return key[static_cast<size_t>(a - first)] < key[static_cast<size_t>(b - first)];
    });
    const auto [lo, hi] = std::minmax_element(key.begin(), key.end());
    most_slabs = slabs_by_thickness((*hi - *lo) / 4.0, X, tets, first, count);
  }
  for (int n_slabs = std::clamp(std::min(count / kMinSlabElements, most_slabs), 1, kMaxSlabs);;
       n_slabs /= 2) {
    BlockSlabs s;
    s.elements = sorted;
    for (int k = 0; k <= n_slabs; ++k)
      s.begin.push_back(static_cast<int>(static_cast<long>(count) * k / n_slabs));
    // Inside a slab the mesh's own order, which keeps neighbouring elements close in memory.
    for (int k = 0; k < n_slabs; ++k) {
      const auto slab_begin = s.elements.begin() + s.begin[static_cast<size_t>(k)];
      const auto slab_end = s.elements.begin() + s.begin[static_cast<size_t>(k) + 1];
      std::sort(slab_begin, slab_end);
      if (kLaneStride > 1) interleave_lanes(std::span<int>(slab_begin, slab_end));
    }
    if (n_slabs <= 2 || slabs_separated(tets, s, X.size())) return s;
  }
}

std::vector<std::vector<int>> make_phases(int n_nodes, const std::vector<Tet>& tets,
                                          const std::vector<Slab>& slabs,
                                          const std::vector<std::span<const int>>& slab_elements) {
  // Slab k of its block: the first slab of a block has k = 0.
  std::vector<std::vector<int>> phases(2);
  int k = 0;
  for (size_t s = 0; s < slabs.size(); ++s) {
    k = (s > 0 && slabs[s].block == slabs[s - 1].block) ? k + 1 : 0;
    phases[static_cast<size_t>(k % 2)].push_back(static_cast<int>(s));
  }
  std::vector<int> owner(static_cast<size_t>(n_nodes), -1);
  for (const std::vector<int>& phase : phases) {
    for (int s : phase)
      for (int e : slab_elements[static_cast<size_t>(s)])
        for (int n : tets[static_cast<size_t>(e)]) {
          int& o = owner[static_cast<size_t>(n)];
          if (o >= 0 && o != s) {  // two slabs of one phase share a node: run them in turn
            std::vector<std::vector<int>> serial;
            for (size_t t = 0; t < slabs.size(); ++t) serial.push_back({static_cast<int>(t)});
            return serial;
          }
          o = s;
        }
    std::fill(owner.begin(), owner.end(), -1);
  }
  if (phases[1].empty()) phases.pop_back();
  return phases;
}

}  // namespace ccm
