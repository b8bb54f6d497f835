// engine/mesh/locality_order.hpp: the same mesh in spatial order.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "engine/mesh/locality_order.hpp"
#include "engine/mesh/structured_box.hpp"

using namespace ccm;

namespace {

// A structured box with its tets and nodes shuffled (a mesher's order), a named surface, a node
// set and two regions.
TetMesh shuffled_box() {
  TetMesh box = structured_box(Vec3(0.04, 0.03, 0.02), 8, 6, 4);
  std::mt19937 random(7);
  std::vector<int> perm(box.nodes.size());
  for (size_t i = 0; i < perm.size(); ++i) perm[i] = static_cast<int>(i);
  std::shuffle(perm.begin(), perm.end(), random);
  TetMesh m = box;
  for (size_t i = 0; i < perm.size(); ++i) m.nodes[static_cast<size_t>(perm[i])] = box.nodes[i];
  for (Tet& t : m.tets)
    for (int& n : t) n = perm[static_cast<size_t>(n)];
  std::shuffle(m.tets.begin(), m.tets.end(), random);
  m.region_names = {"a", "b"};
  for (const Tet& t : m.tets) m.tet_region.push_back(m.nodes[static_cast<size_t>(t[0])].x() < 0.02);
  m.named_surfaces["top"] = {{m.tets[0][0], m.tets[0][1], m.tets[0][2]}};
  m.named_node_sets["some"] = {m.tets[5][0], m.tets[9][3]};
  std::sort(m.named_node_sets["some"].begin(), m.named_node_sets["some"].end());
  return m;
}

std::multiset<std::array<double, 12>> tets_by_position(const TetMesh& m) {
  std::multiset<std::array<double, 12>> out;
  for (const Tet& t : m.tets) {
    std::array<Vec3, 4> x;
    for (int a = 0; a < 4; ++a)
      x[static_cast<size_t>(a)] = m.nodes[static_cast<size_t>(t[static_cast<size_t>(a)])];
    std::array<double, 12> key{};
    for (int a = 0; a < 4; ++a)
      for (int d = 0; d < 3; ++d)
        key[static_cast<size_t>(3 * a + d)] = x[static_cast<size_t>(a)][d];
    out.insert(key);
  }
  return out;
}

// The mean distance in memory between the nodes of a tet: what the element step's gathers span.
double mean_node_span(const TetMesh& m) {
  double sum = 0.0;
  for (const Tet& t : m.tets)
    sum += *std::max_element(t.begin(), t.end()) - *std::min_element(t.begin(), t.end());
  return sum / static_cast<double>(m.tets.size());
}

}  // namespace

TEST_CASE("locality order: the same mesh, its tets and nodes renumbered in spatial order",
          "[mesh][locality]") {
  const TetMesh given = shuffled_box();
  const TetMesh ordered = in_locality_order(given);
  REQUIRE(ordered.nodes.size() == given.nodes.size());
  REQUIRE(ordered.tets.size() == given.tets.size());
  // The same tets, vertex order and all (orientation kept), at the same places.
  CHECK(tets_by_position(ordered) == tets_by_position(given));
  CHECK(mesh_volume(ordered) == Approx(mesh_volume(given)).epsilon(1e-12));
  // Regions, surfaces and node sets follow their tets and nodes.
  std::multiset<std::pair<double, int>> regions_given, regions_ordered;
  for (size_t e = 0; e < given.tets.size(); ++e) {
    regions_given.insert(
        {given.nodes[static_cast<size_t>(given.tets[e][0])].x(), given.tet_region[e]});
    regions_ordered.insert(
        {ordered.nodes[static_cast<size_t>(ordered.tets[e][0])].x(), ordered.tet_region[e]});
  }
  CHECK(regions_given == regions_ordered);
  for (int a = 0; a < 3; ++a)
    CHECK(
        ordered.nodes[static_cast<size_t>(
            ordered.named_surfaces.at("top")[0][static_cast<size_t>(a)])] ==
        given
            .nodes[static_cast<size_t>(given.named_surfaces.at("top")[0][static_cast<size_t>(a)])]);
  std::set<std::array<double, 3>> set_given, set_ordered;
  for (int n : given.named_node_sets.at("some"))
    set_given.insert({given.nodes[n].x(), given.nodes[n].y(), given.nodes[n].z()});
  for (int n : ordered.named_node_sets.at("some"))
    set_ordered.insert({ordered.nodes[n].x(), ordered.nodes[n].y(), ordered.nodes[n].z()});
  CHECK(set_given == set_ordered);
  CHECK(std::is_sorted(ordered.named_node_sets.at("some").begin(),
                       ordered.named_node_sets.at("some").end()));
  // Spatial order: a tet's nodes lie as close in memory as in the box's own lexicographic
  // numbering (about a layer of nodes apart: 9 x 7 here), where the shuffled mesh's lie a
  // third of the mesh apart.
  const double lexicographic = mean_node_span(structured_box(Vec3(0.04, 0.03, 0.02), 8, 6, 4));
  WARN("mean node span: given " << mean_node_span(given) << ", ordered " << mean_node_span(ordered)
                                << ", lexicographic " << lexicographic);
  CHECK(mean_node_span(ordered) < 1.5 * lexicographic);
  CHECK(mean_node_span(given) > 2.0 * lexicographic);
  // Deterministic, and already ordered stays put.
  const TetMesh again = in_locality_order(ordered);
  CHECK(again.tets == ordered.tets);
  CHECK(again.nodes == ordered.nodes);
}
