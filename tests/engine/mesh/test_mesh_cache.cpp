// The mesh cache (engine/mesh/mesh_cache.hpp): a mesh read back is the mesh made, bit for bit; a
// damaged or foreign file is a miss and is replaced; two processes meshing one body at once leave
// one whole file; the folder stays under its bound; with the cache off nothing is written.
#include <fmt/format.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "engine/mesh/gmsh_mesher.hpp"
#include "engine/mesh/mesh_cache.hpp"
#include "tests/support/mesh_cache_scope.hpp"
#include "tests/support/temp_dir.hpp"

using namespace ccm;
namespace fs = std::filesystem;

namespace {

using test::CacheIn;

bool same(const TetMesh& a, const TetMesh& b) { return test::same_mesh(a, b); }

TetMesh labelled_mesh() {
  TetMesh m;
  m.nodes = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1.0 / 3.0)};
  m.tets = {{0, 1, 2, 3}};
  m.named_surfaces["bottom"] = {{0, 2, 1}};
  m.named_node_sets["tip"] = {3};
  m.region_names = {"all"};
  m.tet_region = {0};
  return m;
}

std::vector<fs::path> mesh_files(const fs::path& folder) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(folder)) out.push_back(e.path());
  return out;
}

PrimitiveSpec small_sphere() {
  PrimitiveSpec s{PrimitiveKind::sphere};
  s.radius = 0.01;
  s.mesh_size = 0.004;
  return s;
}

}  // namespace

TEST_CASE("mesh cache: a mesh's bytes read back to the same mesh, a torn one does not",
          "[mesh_cache]") {
  const TetMesh m = labelled_mesh();
  const std::string bytes = mesh_bytes(m);
  TetMesh back;
  REQUIRE(read_mesh_bytes(bytes, back));
  CHECK(same(back, m));
  for (std::size_t cut : {std::size_t{0}, std::size_t{7}, bytes.size() - 1})
    CHECK_FALSE(read_mesh_bytes(bytes.substr(0, cut), back));
  CHECK_FALSE(read_mesh_bytes(bytes + "x", back));
}

TEST_CASE("mesh cache: the second call reads the first's mesh back, bit for bit", "[mesh_cache]") {
  test::TempDir dir;
  const CacheIn cache(dir.path / "meshes");
  int made = 0;
  const auto make = [&] {
    ++made;
    return labelled_mesh();
  };
  const TetMesh first = cached_mesh("key one", make);
  const TetMesh second = cached_mesh("key one", make);
  CHECK(made == 1);
  CHECK(same(first, second));
  cached_mesh("key two", make);
  CHECK(made == 2);
  CHECK(mesh_files(dir.path / "meshes").size() == 2);
}

TEST_CASE("mesh cache: a meshed primitive from the cache is the fresh one, bit for bit",
          "[mesh_cache]") {
  test::TempDir dir;
  TetMesh fresh;
  {
    const CacheIn off(dir.path / "off", std::uintmax_t{1} << 30, false);
    fresh = mesh_primitive(small_sphere(), {});
  }
  CHECK_FALSE(fs::exists(dir.path / "off"));  // the cache off writes nothing
  const CacheIn cache(dir.path / "meshes");
  const MeshCacheStats before = mesh_cache_stats();
  const TetMesh made = mesh_primitive(small_sphere(), {});
  const TetMesh read = mesh_primitive(small_sphere(), {});
  const MeshCacheStats after = mesh_cache_stats();
  CHECK(after.misses == before.misses + 1);
  CHECK(after.hits == before.hits + 1);
  CHECK(same(made, fresh));
  CHECK(same(read, fresh));
  // Placed elsewhere: the same filed mesh, moved.
  Placement moved;
  moved.translation = Vec3(1.0, 2.0, 3.0);
  const TetMesh placed = mesh_primitive(small_sphere(), moved);
  CHECK(mesh_cache_stats().hits == before.hits + 2);
  REQUIRE(placed.nodes.size() == fresh.nodes.size());
  CHECK(placed.nodes[5] == fresh.nodes[5] + moved.translation);
}

TEST_CASE("mesh cache: a damaged file is a miss, remade and replaced", "[mesh_cache]") {
  test::TempDir dir;
  const CacheIn cache(dir.path / "meshes");
  int made = 0;
  const auto make = [&] {
    ++made;
    return labelled_mesh();
  };
  cached_mesh("damaged", make);
  const std::vector<fs::path> files = mesh_files(dir.path / "meshes");
  REQUIRE(files.size() == 1);
  {
    std::fstream f(files[0], std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(-3, std::ios::end);
    f.put('\x7f');  // a flipped byte in the mesh's bytes
  }
  CHECK(same(cached_mesh("damaged", make), labelled_mesh()));
  CHECK(made == 2);
  fs::resize_file(files[0], 20);  // torn
  CHECK(same(cached_mesh("damaged", make), labelled_mesh()));
  CHECK(made == 3);
  CHECK(same(cached_mesh("damaged", make), labelled_mesh()));
  CHECK(made == 3);  // replaced: read back now
}

TEST_CASE("mesh cache: two processes meshing one body at once leave one whole file",
          "[mesh_cache]") {
  test::TempDir dir;
  const CacheIn cache(dir.path / "meshes");
  std::vector<pid_t> children;
  for (int k = 0; k < 2; ++k) {
    const pid_t pid = fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
      for (int i = 0; i < 20; ++i) cached_mesh(fmt::format("shared {}", i % 4), labelled_mesh);
      _exit(0);
    }
    children.push_back(pid);
  }
  for (pid_t pid : children) {
    int status = 0;
    waitpid(pid, &status, 0);
    CHECK(WIFEXITED(status));
  }
  CHECK(mesh_files(dir.path / "meshes").size() == 4);  // no temporary file left
  int made = 0;
  for (int i = 0; i < 4; ++i)
    CHECK(same(cached_mesh(fmt::format("shared {}", i),
                           [&] {
                             ++made;
                             return TetMesh{};
                           }),
               labelled_mesh()));
  CHECK(made == 0);
}

TEST_CASE("mesh cache: the folder stays under its bound, the least recently used going first",
          "[mesh_cache]") {
  test::TempDir dir;
  const std::uintmax_t one = mesh_bytes(labelled_mesh()).size() + 100;  // about one file
  const CacheIn cache(dir.path / "meshes", 3 * one);
  for (int i = 0; i < 10; ++i) cached_mesh(fmt::format("bounded {}", i), labelled_mesh);
  std::uintmax_t total = 0;
  for (const fs::path& f : mesh_files(dir.path / "meshes")) total += fs::file_size(f);
  CHECK(total <= 3 * one);
  int made = 0;
  cached_mesh("bounded 9", [&] {  // the newest stays
    ++made;
    return labelled_mesh();
  });
  CHECK(made == 0);
}
