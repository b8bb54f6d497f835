#include "engine/mesh/mesh_defects.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <numeric>

namespace ccm {
namespace {

constexpr std::size_t kLabelsListed = 10;

std::string first_labels(std::span<const long> labels) {
  const std::size_t n = std::min(labels.size(), kLabelsListed);
  return fmt::format("{}{}", fmt::join(labels.first(n), ", "), labels.size() > n ? ", ..." : "");
}

// The regions of each node's tets, as a sorted list (one entry, 0, without regions).
std::vector<std::vector<int>> node_regions(const TetMesh& mesh) {
  std::vector<std::vector<int>> regions(mesh.nodes.size());
  for (std::size_t e = 0; e < mesh.tets.size(); ++e) {
    const int r = mesh.tet_region.empty() ? 0 : mesh.tet_region[e];
    for (int n : mesh.tets[e]) {
      auto& list = regions[static_cast<std::size_t>(n)];
      if (std::find(list.begin(), list.end(), r) == list.end()) list.push_back(r);
    }
  }
  for (auto& list : regions) std::sort(list.begin(), list.end());
  return regions;
}

bool share_a_region(const std::vector<int>& a, const std::vector<int>& b) {
  for (int r : a)
    if (std::binary_search(b.begin(), b.end(), r)) return true;
  return false;
}

}  // namespace

std::vector<std::size_t> inverted_minority(std::span<const double> six_volumes) {
  const auto negative = static_cast<std::size_t>(
      std::count_if(six_volumes.begin(), six_volumes.end(), [](double v) { return v < 0.0; }));
  const std::size_t positive = six_volumes.size() - negative;
  std::vector<std::size_t> out;
  if (negative == 0 || positive == 0) return out;
  const bool minority_negative = negative <= positive;
  for (std::size_t e = 0; e < six_volumes.size(); ++e)
    if ((six_volumes[e] < 0.0) == minority_negative) out.push_back(e);
  return out;
}

std::string inverted_problem(std::span<const long> labels, std::size_t n_tets,
                             const std::string& element) {
  return fmt::format(
      "{} {} is inverted: its volume has the opposite sign to {} of the {} tetrahedra ({} "
      "inverted: {}); a tangled or wrongly numbered element cannot be simulated",
      element, labels.front(), n_tets - labels.size(), n_tets, labels.size(), first_labels(labels));
}

std::string unused_nodes_problem(std::span<const long> labels, std::size_t file_nodes) {
  return fmt::format(
      "node {} belongs to no tetrahedron ({} of the file's {} nodes do not: {}); ccm simulates "
      "the linear tetrahedra of a file as one body, and a node off them (a reference node, a "
      "shell or beam part) would have no mass or stiffness: remove it",
      labels.front(), labels.size(), file_nodes, first_labels(labels));
}

CoincidentNodes coincident_nodes(const TetMesh& mesh) {
  const std::vector<Vec3>& x = mesh.nodes;
  const auto at = [&](int i) {
    const Vec3& p = x[static_cast<std::size_t>(i)];
    return std::array<double, 3>{p.x(), p.y(), p.z()};
  };
  std::vector<int> order(x.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return at(a) != at(b) ? at(a) < at(b) : a < b; });
  CoincidentNodes out;
  std::vector<std::vector<int>> regions;  // computed on the first coincidence only
  for (std::size_t k = 1; k < order.size(); ++k) {
    if (at(order[k]) != at(order[k - 1])) continue;
    if (regions.empty()) regions = node_regions(mesh);
    const auto& ra = regions[static_cast<std::size_t>(order[k - 1])];
    const auto& rb = regions[static_cast<std::size_t>(order[k])];
    if (!share_a_region(ra, rb)) continue;
    if (out.count == 0) out.first = order[k - 1], out.second = order[k];
    ++out.count;
  }
  return out;
}

std::string coincident_problem(long label_a, long label_b, const Vec3& at, std::size_t count) {
  return fmt::format(
      "nodes {} and {} share the position ({:g}, {:g}, {:g}) ({} node(s) share their position "
      "with another): the tetrahedra on either side are not connected there, a cut the body "
      "would open along; merge the duplicates, or make each part a body (or a region) of its own",
      label_a, label_b, at.x(), at.y(), at.z(), count);
}

}  // namespace ccm
