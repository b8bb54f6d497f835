// What `ccm run` says of the DCR contact search (summary.toml [contact] search, and the table's
// "search" line): the steps its broad phase ran on, the pair cache's rebuilds and the cached pairs
// at the last. On the ball-on-plate example the ball starts clear of the plate, so the broad phase
// is skipped on the first steps (docs/contact-method.md: bodies whose boxes do not overlap), runs
// on the rest, and rebuilds its cache at least once and at most once a searched step.
#include <fmt/format.h>
#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

#include "tests/support/temp_dir.hpp"

namespace fs = std::filesystem;

TEST_CASE("ccm run: the summary says how often the DCR broad phase ran and rebuilt its cache",
          "[dcr][cli]") {
  ccm::test::TempDir dir;
  const fs::path scene = fs::path(CCM_SOURCE_DIR) / "scenes/examples/ball_on_plate_dcr.toml";
  const fs::path out = dir.path / "out";
  const std::string command =
      fmt::format("'{}' run '{}' --out '{}' > '{}' 2>&1", CCM_BINARY, scene.string(), out.string(),
                  (dir.path / "table.txt").string());
  const int status = std::system(command.c_str());
  REQUIRE(WIFEXITED(status));
  REQUIRE(WEXITSTATUS(status) == 0);
  std::stringstream summary;
  summary << std::ifstream(out / "summary.toml").rdbuf();
  const std::string text = summary.str();
  std::smatch m;
  REQUIRE(std::regex_search(text, m, std::regex("\nsteps = ([0-9]+)")));
  const long steps = std::stol(m[1]);
  REQUIRE(std::regex_search(text, m,
                            std::regex("\nsearch = \"dcr: broad phase on ([0-9]+) steps, "
                                       "([0-9]+) pair-cache rebuilds, ([0-9]+) cached pairs")));
  const long searched = std::stol(m[1]), rebuilds = std::stol(m[2]), pairs = std::stol(m[3]);
  INFO(text);
  CHECK(searched > 0);
  CHECK(searched < steps);  // the ball's first steps are far from the plate
  CHECK(rebuilds >= 1);
  CHECK(rebuilds <= searched);
  CHECK(pairs > 0);  // the ball ends on the plate: the last cache holds its pairs
  std::stringstream table;
  table << std::ifstream(dir.path / "table.txt").rdbuf();
  CHECK(table.str().find(fmt::format("broad phase on {} steps", searched)) != std::string::npos);
}
