// Reading a mesh in a child process (engine/mesh/child_reader.hpp): the mesh comes back whole,
// the child's errors and crashes come back as errors, and a child stuck past its deadline is
// killed and the read tried once more.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <stdexcept>

#include "engine/mesh/child_reader.hpp"
#include "engine/mesh/gmsh_mesher.hpp"
#include "tests/support/temp_dir.hpp"

using Catch::Contains;
using namespace ccm;
using namespace std::chrono_literals;

namespace {

TetMesh one_tet() {
  TetMesh m;
  m.nodes = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  m.tets = {Tet{0, 1, 2, 3}};
  m.named_surfaces["base"] = {Triangle{0, 2, 1}};
  return m;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

TEST_CASE("child reader: the mesh comes back whole", "[mesh][child_reader]") {
  const TetMesh back = read_in_child("f.msh", {1s, nullptr}, [] { return one_tet(); });
  CHECK(back.nodes == one_tet().nodes);
  REQUIRE(back.tets.size() == 1);
  CHECK(back.tets[0] == one_tet().tets[0]);
  CHECK(back.named_surfaces.at("base").size() == 1);
}

TEST_CASE("child reader: errors and crashes in the child", "[mesh][child_reader]") {
  CHECK_THROWS_WITH(read_in_child("f.msh", {5s, nullptr},
                                  []() -> TetMesh { throw MeshError("f.msh: line 3: no tets"); }),
                    "f.msh: line 3: no tets");
  CHECK_THROWS_AS(
      read_in_child("f.msh", {5s, nullptr}, []() -> TetMesh { throw std::logic_error("other"); }),
      std::runtime_error);
  CHECK_THROWS_WITH(read_in_child("f.msh", {5s, nullptr},
                                  []() -> TetMesh {
                                    std::raise(SIGSEGV);
                                    return {};
                                  }),
                    Contains("f.msh: Gmsh's reader crashed on the file (signal 11"));
}

TEST_CASE("child reader: a stuck child is killed and the read tried once more",
          "[mesh][child_reader]") {
  test::TempDir dir;
  const std::filesystem::path first = dir.path / "first attempt";
  // Stuck on the first attempt only (the marker file tells the second attempt, a new child).
  const auto stuck_once = [&] {
    if (!std::filesystem::exists(first)) {
      dir.write("first attempt", "");
      ::sleep(30);
    }
    return one_tet();
  };
  auto t0 = std::chrono::steady_clock::now();
  CHECK(read_in_child("f.msh", {300ms, nullptr}, stuck_once).nodes == one_tet().nodes);
  CHECK(seconds_since(t0) < 5.0);  // not the 30 s of the stuck child

  const auto always_stuck = []() -> TetMesh {
    ::sleep(30);
    return {};
  };
  t0 = std::chrono::steady_clock::now();
  CHECK_THROWS_WITH(read_in_child("f.msh", {300ms, nullptr}, always_stuck),
                    "f.msh: the process reading it did not finish within 0.3 s, twice; a file "
                    "this size reads in well under that");
  const double took = seconds_since(t0);
  CHECK(took >= 0.6);  // two deadlines
  CHECK(took < 5.0);
}

TEST_CASE("child reader: the deadline grows with the file", "[mesh][child_reader]") {
  CHECK(reader_deadline(0) == 5000ms);
  CHECK(reader_deadline(64 * 1024) == 5065ms);
  CHECK(reader_deadline(100'000'000) == 105000ms);  // 100 MB: 105 s
}
