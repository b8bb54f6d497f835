// The elements at each node, as compressed rows (CSR): the elements of list k at node n are
// element[first[n] .. first[n + 1]), in list order. Only nodes `keeps(n)` get rows; the others
// have empty ones. The projection updates use it over the elements they prepared.
#pragma once

#include <cstddef>
#include <vector>

#include "engine/mesh/tet_mesh.hpp"

namespace ccm::dcr {

struct NodeElements {
  std::vector<int> first, element;

  template <class Keeps>
  NodeElements(std::size_t n_nodes, const std::vector<Tet>& tets, Keeps keeps) {
    std::vector<int> count(n_nodes, 0);
    for (const Tet& t : tets)
      for (int n : t)
        if (keeps(n)) ++count[static_cast<std::size_t>(n)];
    first.assign(n_nodes + 1, 0);
    for (std::size_t i = 0; i < n_nodes; ++i) first[i + 1] = first[i] + count[i];
    element.resize(static_cast<std::size_t>(first[n_nodes]));
    std::vector<int> next(first.begin(), first.end() - 1);
    for (std::size_t k = 0; k < tets.size(); ++k)
      for (int n : tets[k])
        if (keeps(n))
          element[static_cast<std::size_t>(next[static_cast<std::size_t>(n)]++)] =
              static_cast<int>(k);
  }
  NodeElements() = default;

  int begin(int n) const { return first[static_cast<std::size_t>(n)]; }
  int end(int n) const { return first[static_cast<std::size_t>(n) + 1]; }
  int at(int j) const { return element[static_cast<std::size_t>(j)]; }
};

}  // namespace ccm::dcr
