// The rig's meshes through the mesh cache (rig_models/geometry/rig_mesher.cpp): a part read back
// is the part Gmsh makes, bit for bit, and a change to a length the part is built from, or to
// where the impactor's tip is, meshes afresh instead of serving the old mesh.
#include <catch2/catch.hpp>
#include <filesystem>

#include "rig_models/cases/case_file.hpp"
#include "rig_models/geometry/geometry_file.hpp"
#include "rig_models/geometry/rig_mesher.hpp"
#include "tests/support/mesh_cache_scope.hpp"
#include "tests/support/temp_dir.hpp"

using namespace ccm;
using namespace ccm::rig;

namespace {

const std::filesystem::path kRig = std::filesystem::path(CCM_SOURCE_DIR) / "rig_models";
constexpr double kScale = 2.0;  // twice as coarse: the same code path, a quarter of the time

}  // namespace

TEST_CASE("rig meshes: a part from the cache is the fresh one, bit for bit", "[rig][mesh_cache]") {
  const RigParameters rig = read_case_table(kRig / "cases.toml").rig;
  const RigGeometry geometry = read_geometry(kRig / "geometry.toml");
  const double tip_y = -0.04;
  test::TempDir dir;
  TetMesh fresh_artifact, fresh_impactor;
  {
    const test::CacheIn off(dir.path / "off", std::uintmax_t{1} << 30, false);
    fresh_artifact = mesh_artifact(geometry, rig, kScale);
    fresh_impactor = mesh_impactor(geometry, rig, ImpactorKind::rigid, tip_y, kScale);
  }
  CHECK_FALSE(std::filesystem::exists(dir.path / "off"));
  const test::CacheIn cache(dir.path / "meshes");
  const MeshCacheStats before = mesh_cache_stats();
  const TetMesh made = mesh_artifact(geometry, rig, kScale);
  const TetMesh read = mesh_artifact(geometry, rig, kScale);
  const TetMesh impactor_made = mesh_impactor(geometry, rig, ImpactorKind::rigid, tip_y, kScale);
  const TetMesh impactor_read = mesh_impactor(geometry, rig, ImpactorKind::rigid, tip_y, kScale);
  const MeshCacheStats after = mesh_cache_stats();
  CHECK(after.misses == before.misses + 2);
  CHECK(after.hits == before.hits + 2);
  CHECK(test::same_mesh(made, fresh_artifact));
  CHECK(test::same_mesh(read, fresh_artifact));
  CHECK(test::same_mesh(impactor_made, fresh_impactor));
  CHECK(test::same_mesh(impactor_read, fresh_impactor));
  CHECK_FALSE(read.region_names.empty());  // the parts' names come back with the mesh

  SECTION("another pin diameter is another artifact") {
    RigGeometry wider = geometry;
    wider.artifact.pin_diameter.value *= 1.2;
    const TetMesh other = mesh_artifact(wider, rig, kScale);
    CHECK(mesh_cache_stats().misses == after.misses + 1);
    CHECK_FALSE(test::same_mesh(other, fresh_artifact));
  }
  SECTION("another tip position or impactor kind is another impactor") {
    const TetMesh moved = mesh_impactor(geometry, rig, ImpactorKind::rigid, tip_y + 0.01, kScale);
    const TetMesh flexible = mesh_impactor(geometry, rig, ImpactorKind::flexible, tip_y, kScale);
    CHECK(mesh_cache_stats().misses == after.misses + 2);
    CHECK_FALSE(test::same_mesh(moved, fresh_impactor));
    CHECK_FALSE(test::same_mesh(flexible, fresh_impactor));
  }
}
