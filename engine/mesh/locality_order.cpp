#include "engine/mesh/locality_order.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace ccm {
namespace {

constexpr int kBitsPerAxis = 21;  // 3 x 21 bits in a 64-bit key

// The 21 low bits of v, two zero bits after each (bit i moves to bit 3 i).
std::uint64_t spread_bits(std::uint64_t v) {
  std::uint64_t x = v & 0x1fffffULL;
  x = (x | x << 32) & 0x1f00000000ffffULL;
  x = (x | x << 16) & 0x1f0000ff0000ffULL;
  x = (x | x << 8) & 0x100f00f00f00f00fULL;
  x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2) & 0x1249249249249249ULL;
  return x;
}

// The Morton key of p in the box [lo, lo + span]: its cell on a 2^21 grid per axis, the axes'
// bits interleaved.
std::uint64_t morton_key(const Vec3& p, const Vec3& lo, const Vec3& span) {
  constexpr double kCells = static_cast<double>((1 << kBitsPerAxis) - 1);
  std::uint64_t key = 0;
  for (int d = 0; d < 3; ++d) {
    const double u = std::clamp((p[d] - lo[d]) / span[d], 0.0, 1.0) * kCells;
    key |= spread_bits(static_cast<std::uint64_t>(u)) << d;
  }
  return key;
}

// The tets' order along the curve through their centroids.
std::vector<int> tet_order(const TetMesh& mesh) {
  Vec3 lo = mesh.nodes.front(), hi = mesh.nodes.front();
  for (const Vec3& x : mesh.nodes) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  const Vec3 span = (hi - lo).cwiseMax(Vec3::Constant(1e-300));
  std::vector<std::pair<std::uint64_t, int>> keys(mesh.tets.size());
  for (size_t e = 0; e < mesh.tets.size(); ++e) {
    Vec3 centroid = Vec3::Zero();
    for (int n : mesh.tets[e]) centroid += mesh.nodes[static_cast<size_t>(n)];
    keys[e] = {morton_key(0.25 * centroid, lo, span), static_cast<int>(e)};
  }
  std::sort(keys.begin(), keys.end());  // ties: the given order (the second member)
  std::vector<int> order;
  order.reserve(keys.size());
  for (const auto& k : keys) order.push_back(k.second);
  return order;
}

}  // namespace

TetMesh in_locality_order(TetMesh mesh) {
  if (mesh.tets.empty()) return mesh;
  const std::vector<int> order = tet_order(mesh);
  std::vector<int> new_id(mesh.nodes.size(), -1);  // old node -> new node
  int next = 0;
  std::vector<Tet> tets;
  tets.reserve(mesh.tets.size());
  for (int e : order) {
    Tet t = mesh.tets[static_cast<size_t>(e)];
    for (int& n : t) {
      int& id = new_id[static_cast<size_t>(n)];
      if (id < 0) id = next++;
      n = id;
    }
    tets.push_back(t);
  }
  for (int& id : new_id)  // nodes no tet uses (readers refuse them) keep their relative order
    if (id < 0) id = next++;
  std::vector<Vec3> nodes(mesh.nodes.size());
  for (size_t n = 0; n < new_id.size(); ++n) nodes[static_cast<size_t>(new_id[n])] = mesh.nodes[n];
  if (!mesh.tet_region.empty()) {
    std::vector<int> region;
    region.reserve(order.size());
    for (int e : order) region.push_back(mesh.tet_region[static_cast<size_t>(e)]);
    mesh.tet_region = std::move(region);
  }
  for (auto& [name, triangles] : mesh.named_surfaces)
    for (Triangle& t : triangles)
      for (int& n : t) n = new_id[static_cast<size_t>(n)];
  for (auto& [name, set] : mesh.named_node_sets) {
    for (int& n : set) n = new_id[static_cast<size_t>(n)];
    std::sort(set.begin(), set.end());
  }
  mesh.nodes = std::move(nodes);
  mesh.tets = std::move(tets);
  return mesh;
}

}  // namespace ccm
