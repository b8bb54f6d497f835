// Schema versioning: an older store is migrated in place; foreign or newer files are refused.
#include <catch2/catch.hpp>
#include <fstream>
#include <string>

#include "db/schema/migrations.hpp"
#include "db/store/study_store.hpp"
#include "tests/db/scratch_dir.hpp"
#include "tests/db/store_queries.hpp"

using namespace ccm;

namespace {

std::string file_bytes(const std::filesystem::path& file) {
  std::string bytes(std::filesystem::file_size(file), '\0');
  std::ifstream in(file, std::ios::binary);
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return bytes;
}

std::string open_error(const std::filesystem::path& file) {
  try {
    db::StudyStore store(file);
  } catch (const db::StoreError& e) {
    return e.what();
  }
  return "(opened)";
}

}  // namespace

TEST_CASE("a version-1 store (runs only) is migrated to the latest schema, data kept", "[db]") {
  test::ScratchDir dir("db-migrate");
  const auto file = dir / "old.sqlite";
  {
    db::Connection c(file);
    db::migrate(c, 1);  // what a ccm with only the first migration step wrote
    c.exec(R"sql(
      INSERT INTO studies VALUES (1, 'old', 'g1', '2026-01-01T00:00:00Z', '0.0.9', 'abc');
      INSERT INTO grid_points VALUES (1, 1, 0, 'h0', 100.0, 0.5, 10.0, '');
      INSERT INTO runs (grid_point_id, model, status, grid_hash, ccm_version, git_hash, host,
                        pid, ranks, jobs, started_at)
        VALUES (1, 'ccm', 'completed', 'g1', '0.0.9', 'abc', 'hostA', 42, 1, 1, 'then');)sql");
    CHECK(db::schema_version(c) == 1);
    CHECK(test::count_rows(c, "SELECT count(*) FROM sqlite_schema WHERE name = 'metrics'") == 0);
  }
  db::StudyStore store(file);
  CHECK(db::schema_version(store.connection()) == db::latest_schema_version());
  CHECK(db::latest_schema_version() == 4);
  CHECK(store.study_name() == "old");
  const auto status = store.status();
  REQUIRE(status.size() == 1);
  CHECK(status[0].ccm == db::RunStatus::completed);
  CHECK(status[0].point.modulus_ratio == 100.0);
  // The step-2 tables exist and are usable.
  CHECK(test::count_rows(store.connection(), "SELECT count(*) FROM metrics") == 0);
  CHECK(test::count_rows(store.connection(), "SELECT count(*) FROM fits") == 0);
  // ... and so do the step-3 (benchtop rig) tables.
  CHECK(test::count_rows(store.connection(), "SELECT count(*) FROM rig_runs") == 0);
  // ... and step 4's: fits keyed by the other axes' levels, the grid file.
  CHECK(test::count_rows(store.connection(), "SELECT count(*) FROM study_grids") == 0);
  CHECK(test::count_rows(store.connection(),
                         "SELECT count(*) FROM pragma_table_info('fits') WHERE name = "
                         "'other_axes'") == 1);
  CHECK(test::count_rows(store.connection(), "SELECT count(*) FROM rig_calibrations") == 0);
  CHECK(test::integrity_check(store.connection()) == "ok");
}

TEST_CASE("foreign files are refused with a message naming the file, and left untouched", "[db]") {
  test::ScratchDir dir("db-foreign");
  SECTION("a text file") {
    const auto file = dir / "notes.sqlite";
    std::ofstream(file) << "these are my notes, not a database\n";
    const std::string before = file_bytes(file);
    const std::string error = open_error(file);
    CHECK(error.find(file.string()) != std::string::npos);
    CHECK(error.find("not a ccm study store") != std::string::npos);
    CHECK(file_bytes(file) == before);
  }
  SECTION("another program's SQLite database") {
    const auto file = dir / "other.db";
    {
      db::Connection c(file);
      c.exec("CREATE TABLE customers (id INTEGER PRIMARY KEY, name TEXT)");
    }
    const std::string before = file_bytes(file);
    const std::string error = open_error(file);
    CHECK(error == file.string() +
                       ": an SQLite file with tables but no ccm application_id is not a ccm "
                       "study store; refusing to touch it");
    CHECK(file_bytes(file) == before);
  }
  SECTION("an SQLite file with another application_id") {
    const auto file = dir / "geo.gpkg";
    {
      db::Connection c(file);
      c.exec("PRAGMA application_id = 1196444487");  // GeoPackage, "GPKG"
    }
    CHECK(open_error(file).find("not a ccm study store (application_id 1196444487") !=
          std::string::npos);
  }
  SECTION("a store written by a newer ccm") {
    const auto file = dir / "new.sqlite";
    {
      db::Connection c(file);
      db::migrate(c);
      c.exec("PRAGMA user_version = 99");
    }
    CHECK(open_error(file) == file.string() +
                                  ": schema version 99 was written by a newer ccm (this build "
                                  "knows up to 4); upgrade ccm to open it");
  }
}
