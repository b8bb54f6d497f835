// `ccm study run` on a grid over a scene (docs/grid-file.md, "Grids over your own scene"), end to
// end: every run of the grid is simulated once and stored, each point's ER is its scene's
// E_I / E_A, a second call runs nothing, `study status` and `recommend` read the study as they
// read the thesis grid, and a path that does not exist is refused before anything is written.
#include <fmt/format.h>

#include <catch2/catch.hpp>

#include "db/store/study_store.hpp"
#include "tests/app/cli_shell.hpp"
#include "tests/support/scene_fixtures.hpp"

namespace fs = std::filesystem;
using Catch::Contains;
using namespace ccm;

namespace {

std::string striker_grid(const std::string& axes) {
  return "title = \"striker over a base\"\n[template]\nscene = \"strike.toml\"\n"
         "rigid = [\"striker\"]\n[axes]\n" +
         axes;
}

// Every stored run of the study: (point index, model) -> steps, with the points' ER.
struct StoredStudy {
  std::map<std::pair<int, std::string>, long> steps;
  std::map<int, double> modulus_ratio;
};

StoredStudy stored(const fs::path& db) {
  db::StudyStore store(db);
  REQUIRE(store.open_existing_study());
  StoredStudy s;
  for (const db::PointStatus& p : store.status()) {
    s.modulus_ratio[p.point.index] = p.point.modulus_ratio;
    for (auto m : {study::ImpactModel::ccm, study::ImpactModel::rigid})
      if (const auto run = store.load_run(p.point, m))
        s.steps[{p.point.index, std::string(to_string(m))}] = run->steps;
  }
  return s;
}

}  // namespace

TEST_CASE("ccm study run over a scene: each run once, its groups, status and recommend",
          "[study][template][cli]") {
  test::TempDir dir;
  dir.write("strike.toml", test::kStrikeScene);
  const fs::path grid =
      dir.write("grid.toml", striker_grid("\"bodies.striker.material.E\" = [1e5, 1e7]\n"));
  const fs::path db = dir.path / "s.sqlite";
  const std::string run =
      fmt::format("study run '{}' --db '{}' --quiet", grid.string(), db.string());
  REQUIRE(test::run_ccm(run, dir).status == 0);
  const StoredStudy first = stored(db);
  REQUIRE(first.steps.size() == 4);
  for (const auto& [key, steps] : first.steps) CHECK(steps > 0);
  CHECK(first.modulus_ratio.at(0) == 1.0);  // E_I / E_A = 1e5 / 1e5
  CHECK(first.modulus_ratio.at(1) == 100.0);

  // Again: nothing is run again, the stored runs stay.
  REQUIRE(test::run_ccm(run, dir).status == 0);
  CHECK(stored(db).steps == first.steps);

  const auto status = test::run_ccm(fmt::format("study status --db '{}'", db.string()), dir);
  CHECK(status.status == 0);
  CHECK_THAT(status.out, Contains("2 points: 2 done"));
  CHECK_THAT(status.out, Contains("bodies.striker.material.E: per level of grid axis "
                                  "axes.bodies.striker.material.E: 100000, 1e+07"));
  const auto rec = test::run_ccm(
      fmt::format("recommend --db '{}' --er 100 --rls 0.650311 --ke 1.8e-05", db.string()), dir);
  CHECK(rec.status == 0);
  CHECK_THAT(rec.out, Contains("design point: ER = 100"));
  CHECK_THAT(rec.out, Contains("point 1: ER 100"));
}

TEST_CASE("ccm study run over a scene: a path that is not in the scene is refused, nothing written",
          "[study][template][cli]") {
  test::TempDir dir;
  dir.write("strike.toml", test::kStrikeScene);
  const fs::path grid =
      dir.write("grid.toml", striker_grid("\"bodies.striker.materal.E\" = [1e5, 1e7]\n"));
  const fs::path db = dir.path / "s.sqlite";
  const auto r = test::run_ccm(
      fmt::format("study run '{}' --db '{}' --quiet", grid.string(), db.string()), dir);
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Contains("grid.toml:6: axes.\"bodies.striker.materal.E\"") &&
                        Contains("did you mean \"bodies.striker.material.E\"?"));
  CHECK_FALSE(fs::exists(db));
}

TEST_CASE("ccm study run over a scene under mpirun -np 2 stores the serial study's runs",
          "[study][template][cli][mpi]") {
  // The set-up installs Open MPI (docs/build.md): without mpirun this test fails, never skips.
  REQUIRE(std::system("command -v mpirun > /dev/null 2>&1") == 0);
  test::TempDir dir;
  dir.write("strike.toml", test::kStrikeScene);
  const fs::path grid =
      dir.write("grid.toml", striker_grid("\"bodies.striker.material.E\" = [1e5, 1e7]\n"
                                          "\"bodies.striker.initial_velocity\" = [0.5, 1.0]\n"));
  const fs::path serial = dir.path / "serial.sqlite", ranks = dir.path / "ranks.sqlite";
  REQUIRE(test::run_ccm(
              fmt::format("study run '{}' --db '{}' --quiet", grid.string(), serial.string()), dir)
              .status == 0);
  // Open MPI's own allocations are not ours to leak-check under the sanitizer build.
  const auto mpi = test::run_command(
      fmt::format("ASAN_OPTIONS=detect_leaks=0 mpirun --allow-run-as-root --oversubscribe -np 2 "
                  "'{}' study run '{}' --db '{}' --quiet",
                  CCM_BINARY, grid.string(), ranks.string()),
      dir);
  INFO(mpi.err);
  REQUIRE(mpi.status == 0);
  const StoredStudy a = stored(serial), b = stored(ranks);
  REQUIRE(a.steps.size() == 8);
  CHECK(a.steps == b.steps);  // deterministic runs: the same steps on one rank or two
  CHECK(a.modulus_ratio == b.modulus_ratio);
}

TEST_CASE("ccm study refine under mpirun is refused, nothing run", "[study][refine][cli]") {
  test::TempDir dir;
  // What mpirun sets for every rank it starts (run/parallel/rank_context.hpp).
  const auto r = test::run_command(fmt::format("OMPI_COMM_WORLD_SIZE=2 '{}' study refine --db '{}'",
                                               CCM_BINARY, (dir.path / "s.sqlite").string()),
                                   dir);
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Contains("study refine runs in one process"));
  CHECK_FALSE(fs::exists(dir.path / "s.sqlite"));
}
