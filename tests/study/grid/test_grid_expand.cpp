// Grid expansion: count, row-major order (ER, RLS, KE, then other axes by name), indices,
// convergence runs after the grid.
#include <catch2/catch.hpp>
#include <string>

#include "study/grid/grid_expand.hpp"
#include "study/grid/grid_file.hpp"
#include "tests/study/grid/grid_fixtures.hpp"

using ccm::test::kSmallGrid;
using ccm::test::small_grid_with;
using namespace ccm::study;

namespace {

void check_point(const GridPoint& p, int index, double er, double rls, double ke) {
  INFO("point " << index);
  CHECK(p.index == index);
  CHECK(p.modulus_ratio == er);
  CHECK(p.length_ratio == rls);
  CHECK(p.kinetic_energy == ke);
}

}  // namespace

TEST_CASE("the thesis grid expands to 36 points, ER outermost and KE innermost", "[grid]") {
  const GridSpec g = parse_grid_file(CCM_SOURCE_DIR "/scenes/grids/thesis.toml");
  const std::vector<GridPoint> points = expand_grid(g);
  REQUIRE(points.size() == 36);
  CHECK(grid_size(g) == 36);
  for (size_t i = 0; i < points.size(); ++i) CHECK(points[i].index == static_cast<int>(i));
  check_point(points[0], 0, 1.0, 0.5, 10.0);
  check_point(points[1], 1, 1.0, 0.5, 50.0);
  check_point(points[3], 3, 1.0, 1.0, 10.0);
  check_point(points[9], 9, 1e2, 0.5, 10.0);
  check_point(points[35], 35, 1e6, 1.5, 100.0);
  for (const GridPoint& p : points) CHECK(p.other_axes.empty());
}

TEST_CASE("other axes are swept inside KE, in name order, values in file order", "[grid]") {
  const GridSpec g =
      parse_grid(small_grid_with("KE = [10.0, 100.0]",
                                 "KE = [10.0, 100.0]\npenalty = [1e5, 1e4]\nnu = [0.3, 0.45]"),
                 "g.toml");
  const std::vector<GridPoint> points = expand_grid(g);
  REQUIRE(points.size() == 2 * 3 * 2 * 2 * 2);
  // Within one (ER, RLS, KE): nu before penalty (name order), penalty fastest.
  const std::vector<std::pair<double, double>> nu_penalty = {
      {0.3, 1e5}, {0.3, 1e4}, {0.45, 1e5}, {0.45, 1e4}};
  for (size_t i = 0; i < 8; ++i) {
    INFO("point " << i);
    CHECK(points[i].other_axes.at("nu") == nu_penalty[i % 4].first);
    CHECK(points[i].other_axes.at("penalty") == nu_penalty[i % 4].second);
    CHECK(points[i].kinetic_energy == (i < 4 ? 10.0 : 100.0));
  }
  check_point(points[8], 8, 1.0, 1.0, 10.0);
  CHECK(points.back().index == 47);
}

TEST_CASE("convergence runs: each point at each mesh scale, indices after the grid", "[grid]") {
  const GridSpec g = parse_grid_file(CCM_SOURCE_DIR "/scenes/grids/thesis.toml");
  const std::vector<GridPoint> runs = expand_convergence(g);
  // The eight corners (ER 1, 1e6) x (RLS 0.5, 1.5) x (KE 10, 100), ER outermost, KE fastest.
  REQUIRE(runs.size() == 8 * 3);
  const std::vector<double> scales = {1.0, 0.75, 0.5};
  for (size_t i = 0; i < runs.size(); ++i) {
    INFO("run " << i);
    const size_t corner = i / 3;
    CHECK(runs[i].index == 36 + static_cast<int>(i));
    CHECK(runs[i].other_axes.size() == 1);
    CHECK(runs[i].other_axes.at("mesh_scale") == scales[i % 3]);
    CHECK(runs[i].modulus_ratio == (corner < 4 ? 1.0 : 1e6));
    CHECK(runs[i].length_ratio == (corner % 4 < 2 ? 0.5 : 1.5));
    CHECK(runs[i].kinetic_energy == (corner % 2 == 0 ? 10.0 : 100.0));
  }
  CHECK(expand_convergence(parse_grid(kSmallGrid, "g.toml")).empty());
}

TEST_CASE("expansion is deterministic", "[grid]") {
  const GridSpec g = parse_grid(
      small_grid_with("KE = [10.0, 100.0]", "KE = [100.0, 10.0]\nnu = [0.45, 0.3]"), "g.toml");
  const std::vector<GridPoint> a = expand_grid(g);
  const std::vector<GridPoint> b = expand_grid(g);
  REQUIRE(a.size() == b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    CHECK(a[i].index == b[i].index);
    CHECK(a[i].modulus_ratio == b[i].modulus_ratio);
    CHECK(a[i].length_ratio == b[i].length_ratio);
    CHECK(a[i].kinetic_energy == b[i].kinetic_energy);
    CHECK(a[i].other_axes == b[i].other_axes);
  }
  CHECK(a[0].kinetic_energy == 100.0);  // file order, not sorted
  CHECK(a[0].other_axes.at("nu") == 0.45);
}
