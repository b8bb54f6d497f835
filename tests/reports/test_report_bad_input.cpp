// `ccm report` on bad input: each a clear message naming the file, exit code 2, nothing written;
// and an older store, migrated in memory (the file unchanged) and reported.
#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "db/schema/migrations.hpp"
#include "db/sqlite/connection.hpp"
#include "db/store/provenance.hpp"
#include "db/store/study_store.hpp"
#include "tests/reports/synthetic_study.hpp"
#include "tests/reports/text_file.hpp"
#include "tests/support/temp_dir.hpp"

namespace ccm {
namespace {

namespace fs = std::filesystem;

struct CommandResult {
  int exit_code = -1;
  std::string error;  // its standard error
};

CommandResult run_report(const test::TempDir& dir, const fs::path& db) {
  const fs::path err = dir.path / "stderr.txt";
  const std::string command = std::string(CCM_BINARY) + " report --db '" + db.string() +
                              "' --out '" + (dir.path / "report").string() + "' 2>'" +
                              err.string() + "' >/dev/null";
  const int status = std::system(command.c_str());
  std::ifstream in(err);
  std::ostringstream text;
  text << in.rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

void check_refused(const test::TempDir& dir, const fs::path& db, const std::string& why) {
  const CommandResult r = run_report(dir, db);
  INFO(r.error);
  CHECK(r.exit_code == 2);
  CHECK(r.error.find(db.string()) != std::string::npos);
  CHECK(r.error.find(why) != std::string::npos);
  CHECK_FALSE(fs::exists(dir.path / "report"));
}

TEST_CASE("ccm report refuses a missing, foreign, newer or empty database, or an unrun study",
          "[reports]") {
  test::TempDir dir;
  SECTION("missing file") {
    check_refused(dir, dir.path / "nope.sqlite", "no such study database");
  }
  SECTION("a text file") {
    check_refused(dir, dir.write("notes.sqlite", "not a database at all, just text\n"),
                  "not a ccm study store");
  }
  SECTION("an SQLite file of another application") {
    const fs::path file = dir.path / "other.sqlite";
    db::Connection(file).exec("CREATE TABLE customers (id INTEGER PRIMARY KEY, name TEXT)");
    check_refused(dir, file, "not a ccm study store");
  }
  SECTION("a store of a newer schema") {
    const fs::path file = dir.path / "newer.sqlite";
    {
      db::Connection c(file);
      db::migrate(c);
      c.exec("PRAGMA user_version = " + std::to_string(db::latest_schema_version() + 1));
    }
    check_refused(dir, file, "newer ccm");
  }
  SECTION("a store without a study") {
    const fs::path file = dir.path / "fresh.sqlite";
    db::StudyStore{file};
    check_refused(dir, file, "holds no study");
  }
  SECTION("a study without grid points") {
    const fs::path file = dir.path / "empty.sqlite";
    db::StudyStore(file).open_study("empty-study", "hash");
    check_refused(dir, file, "no grid points");
  }
  SECTION("a study whose runs are all pending, running or failed") {
    const fs::path file = dir.path / "unrun.sqlite";
    {
      db::StudyStore store(file);
      store.open_study("unrun-study", "hash");
      const study::GridPoint a{0, 1.0, 0.5, 10.0, {}}, b{1, 1e2, 0.5, 10.0, {}};
      store.add_grid_point(a);
      store.add_grid_point(b);
      const auto provenance = db::current_provenance("hash");
      store.mark_running(a, study::ImpactModel::ccm, provenance, db::utc_now());
      store.record_failure(a, study::ImpactModel::rigid, "mesh generation failed", provenance);
    }
    check_refused(dir, file,
                  "has 2 grid points but no completed or unstable run yet (1 of its 4 "
                  "runs failed");
  }
}

TEST_CASE("ccm report reads a store of an older schema (migrated in memory, the file unchanged)",
          "[reports]") {
  test::TempDir dir;
  const fs::path file = dir.path / "old.sqlite";
  {
    db::Connection c(file);
    db::migrate(c, 1);  // the run ledger only, before metrics and fits existed
    c.exec(
        "INSERT INTO studies (name, grid_hash, created_at, ccm_version, git_hash) "
        "VALUES ('old-study', 'h', '2026-01-01T00:00:00Z', '0.0.1', 'abc')");
  }
  // Migrated, then refused for what it holds (a study of no points), not for its schema; a
  // reading command writes nothing, so the file keeps its version.
  check_refused(dir, file, "no grid points");
  db::Connection c(file);
  CHECK(db::schema_version(c) == 1);
}

TEST_CASE("ccm report reads an older store holding runs and reports them", "[reports]") {
  test::TempDir dir;
  const fs::path file = dir.path / "v1.sqlite";
  test::write_synthetic_study(file);
  {
    // A schema-1 store: the run ledger (schema step 1) without the tables and columns of steps
    // 2-10.
    db::Connection c(file);
    c.exec("DROP TABLE validation_scores; DROP TABLE validation_curves; DROP TABLE validations;");
    c.exec("DROP TABLE rig_calibration_trials;");       // step 10's
    c.exec("DROP TABLE rig_calibration_predictions;");  // step 8's
    c.exec(
        "DROP TABLE rig_calibration_evaluations; DROP TABLE rig_calibration_parameters; "
        "DROP TABLE rig_calibrations; DROP TABLE rig_measured_samples; "
        "DROP TABLE rig_channel_samples; DROP TABLE rig_contact; "
        "DROP TABLE rig_channel_spread; DROP TABLE rig_channel_metrics; DROP TABLE rig_runs;");
    c.exec("DROP TABLE fit_points; DROP TABLE fit_terms; DROP TABLE fits; DROP TABLE metrics;");
    for (const char* column : {"step_cpu_seconds", "step_wall_seconds", "dt_first", "dt_mean",
                               "steps_structure", "steps_contact", "steps_max_dt", "steps_landing",
                               "dt_contact_min", "reuses_run_id"})  // step 4's
      c.exec(std::string("ALTER TABLE runs DROP COLUMN ") + column);
    c.exec("DROP TABLE study_grids;");  // step 5's
    c.exec("DROP TABLE comparisons;");  // step 6's
    c.exec("PRAGMA user_version = 1");
  }
  const fs::path out = dir.path / "report";
  const std::string command = std::string(CCM_BINARY) + " report --db '" + file.string() +
                              "' --out '" + out.string() + "' >'" +
                              (dir.path / "stdout.txt").string() + "' 2>&1";
  const int status = std::system(command.c_str());
  const std::string printed = test::read_text(dir.path / "stdout.txt");
  INFO(printed);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(printed.find((out / "index.html").string()) != std::string::npos);
  const std::string html = test::read_text(out / "index.html");
  CHECK(html.find("No metrics are stored for this study") != std::string::npos);
  CHECK(fs::exists(out / "fig-total-runtime.svg"));  // the runs are reported
  CHECK(fs::exists(out / "fig-convergence-error-vs-time.svg"));
  db::Connection c(file);
  CHECK(db::schema_version(c) == 1);  // read in an in-memory copy: the file is not migrated
}

}  // namespace
}  // namespace ccm
