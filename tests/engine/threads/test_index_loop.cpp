// for_each_index (engine/threads/index_loop.hpp): every index once, and a loop that is not to run
// in parallel enters no OpenMP region at all (omp_get_level counts inactive regions too: a region
// of one thread, as `#pragma omp parallel if (false)` makes, is level 1).
// Compiled with OpenMP (tests/CMakeLists.txt).
#include <omp.h>

#include <catch2/catch.hpp>
#include <cstddef>
#include <vector>

#include "engine/threads/index_loop.hpp"

namespace {

struct Visits {
  std::vector<int> count, level;
  explicit Visits(std::size_t n) : count(n, 0), level(n, -1) {}
};

Visits visit(std::size_t n, int threads, bool parallel) {
  Visits v(n);
  ccm::for_each_index(n, threads, parallel, [&](std::size_t i) {
    ++v.count[i];
    v.level[i] = omp_get_level();
  });
  return v;
}

}  // namespace

TEST_CASE("index loop: on the calling thread it enters no OpenMP region", "[threads]") {
  const Visits v = visit(10000, 2, false);
  for (std::size_t i = 0; i < v.count.size(); ++i) {
    REQUIRE(v.count[i] == 1);
    REQUIRE(v.level[i] == 0);
  }
  // What the helper avoids: a region with a false `if` clause is still a region (of one thread).
  int level_in_if_false = -1;
  const bool no = omp_get_max_threads() < 0;  // false, unknown to the compiler
#pragma omp parallel num_threads(2) if (no)
  level_in_if_false = omp_get_level();
  CHECK(level_in_if_false == 1);
}

TEST_CASE("index loop: on threads every index once, inside one region", "[threads]") {
  const Visits v = visit(10000, 2, true);
  for (std::size_t i = 0; i < v.count.size(); ++i) {
    REQUIRE(v.count[i] == 1);
    REQUIRE(v.level[i] == 1);
  }
  const Visits none = visit(0, 2, true);
  CHECK(none.count.empty());
}
