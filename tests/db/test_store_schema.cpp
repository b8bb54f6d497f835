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
  CHECK(db::latest_schema_version() == 10);
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
  // ... and step 8's: a calibration's left-out cases and its parameters' spread.
  CHECK(test::count_rows(store.connection(), "SELECT count(*) FROM rig_calibration_predictions") ==
        0);
  CHECK(test::count_rows(store.connection(),
                         "SELECT count(*) FROM pragma_table_info('rig_calibration_parameters') "
                         "WHERE name IN ('curvature', 'half_width')") == 2);
  // ... and step 5's: fits keyed by the other axes' levels, the grid file.
  CHECK(test::count_rows(store.connection(), "SELECT count(*) FROM study_grids") == 0);
  CHECK(test::count_rows(store.connection(),
                         "SELECT count(*) FROM pragma_table_info('fits') WHERE name = "
                         "'other_axes'") == 1);
  CHECK(test::count_rows(store.connection(), "SELECT count(*) FROM rig_calibrations") == 0);
  CHECK(test::integrity_check(store.connection()) == "ok");
}

TEST_CASE("a version-3 store's runs and metrics migrate without an invented measured cost",
          "[db]") {
  test::ScratchDir dir("db-migrate-cost");
  const auto file = dir / "v3.sqlite";
  {
    db::Connection c(file);
    db::migrate(c, 3);  // what a ccm before the measured cost wrote
    c.exec(R"sql(
      INSERT INTO studies VALUES (1, 'old', 'g1', '2026-01-01T00:00:00Z', '0.0.9', 'abc');
      INSERT INTO grid_points VALUES (1, 1, 0, 'h0', 100.0, 0.5, 10.0, '');
      INSERT INTO grid_points VALUES (2, 1, 1, 'h1', 1.0, 0.5, 10.0, '');
      INSERT INTO runs (grid_point_id, model, status, steps, wall_seconds, initial_stable_dt,
                        average_iteration_seconds, grid_hash, ccm_version, git_hash, host, pid,
                        ranks, jobs, started_at)
        VALUES (1, 'rigid', 'completed', 9000, 3.0, 1e-3, 3.3e-4, 'g1', '0.0.9', 'abc', 'hostA',
                42, 1, 1, 'then');
      INSERT INTO metrics (grid_point_id, usable, nt_ccm, nt_rigid, tr_ccm, tr_rigid, rtr,
                           w_u_mean, final_u_mean, computed_at)
        VALUES (1, 1, 40.0, 0.33, 6.0, 0.05, 121.0, 0.001, 0.2, 'then');
      INSERT INTO metrics (grid_point_id, usable, excluded_reason, computed_at)
        VALUES (2, 0, 'rigid run unstable: energy', 'then');
      INSERT INTO fits (id, study_id, metric, kinetic_energy, degree_log_er, degree_rls,
                        r_squared, loo_rmse, n_points, fitted_at)
        VALUES (1, 1, 'rtr', 10.0, 1, 0, 0.9, 1.0, 4, 'then'),
               (2, 1, 'final_u_mean', 10.0, 1, 0, 0.9, 1.0, 4, 'then');
      INSERT INTO fit_terms VALUES (1, 0, 0, 1.0), (2, 0, 0, 2.0);)sql");
    // Step 4 alone: fits of RTR (and of w = error / RTR) were fits of the estimate: removed; the
    // others stay (step 5 then drops every v2 fit: they are refitted from the metrics).
    db::migrate(c, 4);
    CHECK(test::count_rows(c, "SELECT count(*) FROM fits") == 1);
    CHECK(test::count_rows(c, "SELECT count(*) FROM fits WHERE metric = 'final_u_mean'") == 1);
    CHECK(test::count_rows(c, "SELECT count(*) FROM fit_terms") == 1);
  }
  db::StudyStore store(file);
  db::Connection& c = store.connection();
  CHECK(db::schema_version(c) == 10);
  // The old run keeps its figures; what was not measured stays NULL, not a made-up number.
  CHECK(test::count_rows(c,
                         "SELECT count(*) FROM runs WHERE steps = 9000 AND "
                         "step_cpu_seconds IS NULL AND steps_contact IS NULL AND "
                         "dt_first IS NULL AND reuses_run_id IS NULL") == 1);
  // The thesis's estimate moves to its own columns; the measured ones are unknown, and so are
  // the weighting functions divided by it; the point is left out of the fits, saying why.
  const auto metrics = store.load_metrics();
  REQUIRE(metrics.size() == 2);
  CHECK_FALSE(metrics[0].usable);
  CHECK(metrics[0].excluded_reason.find("measured cost unknown") != std::string::npos);
  CHECK(metrics[0].runtime_ratio == 0.0);  // NULL in the store
  CHECK(metrics[0].runtime_ratio_thesis_estimate == 121.0);
  CHECK(metrics[0].ccm.total_runtime_thesis_estimate == 6.0);
  CHECK(metrics[0].rigid.total_runtime_thesis_estimate == 0.05);
  CHECK(metrics[0].final_state.u_mean == 0.2);  // the errors are kept
  CHECK_FALSE(metrics[0].impact_errors);        // no designer's metrics before schema 7
  CHECK(test::count_rows(c,
                         "SELECT count(*) FROM metrics WHERE rtr IS NOT NULL OR "
                         "tr_ccm IS NOT NULL OR w_u_mean IS NOT NULL") == 0);
  // An unusable point keeps its own reason.
  CHECK(metrics[1].excluded_reason == "rigid run unstable: energy");
  CHECK(test::count_rows(c, "SELECT count(*) FROM fits") == 0);
  CHECK(test::integrity_check(c) == "ok");
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
                                  "knows up to 10); upgrade ccm to open it");
  }
  SECTION("a store whose schema version is negative (a damaged header; found by fuzzing)") {
    const auto file = dir / "damaged.sqlite";
    {
      db::Connection c(file);
      db::migrate(c);
      c.exec("PRAGMA user_version = -242");
    }
    CHECK(open_error(file) == file.string() +
                                  ": schema version -242 is negative: the file's header is "
                                  "damaged (not a ccm study store)");
  }
}
