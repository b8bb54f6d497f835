// ccm installs like a tool: `cmake --install BUILD --prefix P` puts the executable, the rig data,
// the example scenes and trials and the docs under P, and the executable finds its data relative
// to itself, so that P can be moved and ccm run from anywhere.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "tests/app/cli_shell.hpp"

namespace ccm {
namespace {

namespace fs = std::filesystem;

std::string shell_quoted(const fs::path& p) { return "'" + p.string() + "'"; }

}  // namespace

TEST_CASE("cmake --install puts ccm and its data under a prefix that can be moved",
          "[cli][install]") {
  test::TempDir dir;
  const fs::path build = fs::path(CCM_BINARY).parent_path();
  const fs::path first = dir.path / "first-prefix";
  const auto install = test::run_command(
      "cmake --install " + shell_quoted(build) + " --prefix " + shell_quoted(first), dir);
  INFO(install.out << install.err);
  REQUIRE(install.status == 0);
  for (const char* file :
       {"bin/ccm", "share/ccm/rig/cases.toml", "share/ccm/rig/geometry.toml",
        "share/ccm/scenes/examples/sphere_on_plate.toml", "share/ccm/scenes/grids/default.toml",
        "share/ccm/examples/rig-dev/RX025_t2.csv", "share/ccm/examples/rig-dev/README.md",
        "share/doc/ccm/README.md", "share/doc/ccm/docs/measurements.md",
        "share/doc/ccm/docs/store.md"}) {
    INFO(file);
    CHECK(fs::is_regular_file(first / file));
  }

  // Moved, then run from another folder: the data are found beside the executable.
  const fs::path moved = dir.path / "moved" / "ccm-0";
  fs::create_directories(moved.parent_path());
  fs::rename(first, moved);
  const fs::path elsewhere = dir.path / "elsewhere";
  fs::create_directories(elsewhere);
  const std::string ccm = "cd " + shell_quoted(elsewhere) + " && env -u CCM_DATA_DIR " +
                          shell_quoted(moved / "bin" / "ccm");
  const auto list = test::run_command(ccm + " rig list --json", dir);
  INFO(list.err);
  REQUIRE(list.status == 0);
  const nlohmann::json cases = nlohmann::json::parse(list.out);
  CHECK(cases["case_file"] == (moved / "share/ccm/rig/cases.toml").string());
  CHECK(cases["cases"].size() == 12);
  const auto help = test::run_command(ccm + " rig run --help", dir);
  CHECK_THAT(help.out, Catch::Contains((moved / "share/ccm/rig/geometry.toml").string()));
  // The installed example scene reads (`ccm study scene` prints a point of a grid).
  const auto scene = test::run_command(
      ccm + " study scene " + shell_quoted(moved / "share/ccm/scenes/grids/default.toml") + " -p 0",
      dir);
  INFO(scene.err);
  CHECK(scene.status == 0);

  // The executable without its data: refused, naming where it looked and what to do.
  const fs::path lonely = dir.path / "lonely";
  fs::create_directories(lonely);
  fs::copy_file(moved / "bin" / "ccm", lonely / "ccm");
  const auto alone =
      test::run_command("env -u CCM_DATA_DIR " + shell_quoted(lonely / "ccm") + " rig list", dir);
  CHECK(alone.status == 2);
  CHECK_THAT(alone.err, Catch::Contains("no ccm data folder holding rig/cases.toml"));
  CHECK_THAT(alone.err, Catch::Contains((lonely / "share" / "ccm").string()));
  CHECK_THAT(alone.err, Catch::Contains("CCM_DATA_DIR"));
  // ... and with CCM_DATA_DIR naming the data folder, it runs.
  const auto pointed = test::run_command("CCM_DATA_DIR=" + shell_quoted(moved / "share/ccm") + " " +
                                             shell_quoted(lonely / "ccm") + " rig list",
                                         dir);
  CHECK(pointed.status == 0);
  CHECK_THAT(pointed.out, Catch::Contains("RX025"));
}

}  // namespace ccm
