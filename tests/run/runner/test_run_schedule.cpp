// The order in which a study's runs are handed out (app/run_schedule.hpp): longest first,
// deterministic, and a counter that forked workers share without handing a number out twice.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <set>
#include <vector>

#include "app/run_schedule.hpp"
#include "study/grid/grid_file.hpp"
#include "tests/study/grid/grid_fixtures.hpp"

using namespace ccm;
using namespace ccm::study;

TEST_CASE("runs are handed out longest first", "[study][schedule]") {
  std::string text(ccm::test::kSmallGrid);
  text +=
      "\n[convergence]\npoints = [{ ER = 100.0, RLS = 0.5, KE = 10.0 }]\nmesh_scales = [1.0, "
      "0.5]\n";
  const GridSpec g = parse_grid(text, "g.toml");
  const std::vector<PlannedRun> runs = plan_runs(g, study::study_points(g));
  REQUIRE(runs.size() == 2 * (12 + 2));
  const std::vector<std::size_t> order = longest_first(runs);
  REQUIRE(order.size() == runs.size());
  CHECK(std::set<std::size_t>(order.begin(), order.end()).size() == runs.size());  // a permutation
  // First the rigid run at half the mesh size (60 x 16 = 960), then the CCM one (10 x 16), then
  // the rigid runs at full size (60), the ER 100 CCM runs (10), the ER 1 CCM runs (1); ties in
  // plan order.
  CHECK(runs[order[0]].model == ImpactModel::rigid);
  CHECK(runs[order[0]].point.other_axes.at("mesh_scale") == 0.5);
  CHECK(runs[order[1]].model == ImpactModel::ccm);
  CHECK(runs[order[1]].point.other_axes.at("mesh_scale") == 0.5);
  CHECK(expected_run_cost(runs[order[1]].point, ImpactModel::ccm) == Approx(160.0));
  CHECK(runs[order.back()].model == ImpactModel::ccm);
  CHECK(runs[order.back()].point.modulus_ratio == 1.0);
  for (std::size_t k = 1; k < order.size(); ++k) {
    const PlannedRun& a = runs[order[k - 1]];
    const PlannedRun& b = runs[order[k]];
    const double ca = expected_run_cost(a.point, a.model), cb = expected_run_cost(b.point, b.model);
    CHECK(ca >= cb);
    if (ca == cb) CHECK(order[k - 1] < order[k]);
  }
  CHECK(longest_first(runs) == order);
}

TEST_CASE("a shared counter hands each number to one forked worker only", "[study][schedule]") {
  SharedCounter counter;
  int fds[2];
  REQUIRE(pipe(fds) == 0);
  constexpr std::size_t kTotal = 2000;
  std::vector<pid_t> children;
  for (int w = 0; w < 3; ++w) {
    const pid_t pid = fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
      for (std::size_t k = counter.next(); k < kTotal; k = counter.next())
        if (write(fds[1], &k, sizeof k) != sizeof k) _exit(1);
      _exit(0);
    }
    children.push_back(pid);
  }
  close(fds[1]);
  std::vector<std::size_t> got;
  std::size_t k = 0;
  while (read(fds[0], &k, sizeof k) == static_cast<ssize_t>(sizeof k)) got.push_back(k);
  close(fds[0]);
  for (pid_t pid : children) {
    int status = 0;
    waitpid(pid, &status, 0);
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
  }
  std::sort(got.begin(), got.end());
  REQUIRE(got.size() == kTotal);
  for (std::size_t i = 0; i < kTotal; ++i) CHECK(got[i] == i);
}

TEST_CASE("the workers of a study share the cores between them", "[study][schedule][threads]") {
  CHECK(threads_per_job(2, 1) == 2);  // one worker: every core
  CHECK(threads_per_job(2, 2) == 1);
  CHECK(threads_per_job(8, 3) == 2);  // never more threads than cores in total
  CHECK(threads_per_job(2, 4) == 1);  // at least one
}
