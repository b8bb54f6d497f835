// The reading commands and the store file: `ccm study status` never writes a file (a missing
// or empty file stays so, a store stays byte for byte, nothing appears beside it), `--json`,
// and a store renamed or moved together with its histories folder still reports.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "db/schema/migrations.hpp"
#include "db/sqlite/connection.hpp"
#include "db/store/study_store.hpp"
#include "records/grid_point.hpp"
#include "tests/app/cli_shell.hpp"
#include "tests/reports/synthetic_study.hpp"

namespace ccm {
namespace {

namespace fs = std::filesystem;

// Every file under `folder` (recursively) with its content.
std::map<std::string, std::string> snapshot(const fs::path& folder) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    if (entry.is_regular_file())
      files[fs::relative(entry.path(), folder).string()] = test::file_text(entry.path());
  return files;
}

std::string status_of(const fs::path& db) { return "study status --db '" + db.string() + "'"; }

// A study written through the store API (no simulation): tests/reports/synthetic_study.hpp.
fs::path synthetic_store(const test::TempDir& dir, const std::string& name) {
  const fs::path folder = dir.path / "stores";
  fs::create_directories(folder);
  test::write_synthetic_study(folder / name);
  return folder / name;
}

const study::GridPoint kFirstPoint{0, 1.0, 0.5, 10.0, {}};  // the synthetic grid's point 0

}  // namespace

TEST_CASE(
    "ccm study status writes nothing: a missing or empty file is refused, a store is "
    "left as it was",
    "[cli][store]") {
  test::TempDir dir;
  SECTION("a missing file is refused and not created") {
    const auto r = test::run_ccm(status_of(dir.path / "missing.sqlite"), dir);
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains("no such study database"));
    CHECK_FALSE(fs::exists(dir.path / "missing.sqlite"));
  }
  SECTION("an empty file is refused and stays empty") {
    const fs::path empty = dir.write("empty.sqlite", "");
    const auto r = test::run_ccm(status_of(empty), dir);
    INFO(r.err);
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains(empty.string() + ": not a ccm study store"));
    CHECK(fs::file_size(empty) == 0);
    CHECK_FALSE(fs::exists(empty.string() + "-wal"));
    CHECK_FALSE(fs::exists(empty.string() + "-shm"));
  }
  SECTION("a text file is refused and left alone") {
    const fs::path text = dir.write("notes.sqlite", "not a database\n");
    const auto r = test::run_ccm(status_of(text), dir);
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains("not a ccm study store"));
    CHECK(test::file_text(text) == "not a database\n");
  }
  SECTION("a store: the same bytes, no -wal or -shm beside it, for text and JSON") {
    const fs::path db = synthetic_store(dir, "s.sqlite");
    const auto before = snapshot(db.parent_path());
    for (const char* extra : {"", " --json"}) {
      const auto r = test::run_ccm(status_of(db) + extra, dir);
      INFO(r.err);
      CHECK(r.status == 0);
      CHECK(snapshot(db.parent_path()) == before);
    }
  }
  SECTION("a store of an older schema is read (migrated in memory) and not changed") {
    const fs::path db = synthetic_store(dir, "old.sqlite");
    {
      db::Connection c(db);  // back to schema 4: without the tables and columns of steps 5-10
      c.exec(
          "DROP TABLE rig_calibration_trials; DROP TABLE validation_scores; DROP TABLE "
          "validation_curves; DROP TABLE validations; "
          "DROP TABLE comparisons; DROP TABLE study_grids; DROP TABLE rig_calibration_predictions; "
          "ALTER TABLE rig_calibration_parameters DROP COLUMN curvature; ALTER TABLE "
          "rig_calibration_parameters DROP COLUMN half_width; PRAGMA user_version = 4");
      for (const char* column :
           {"peak_force_ccm", "peak_force_rigid", "indentation_ccm", "indentation_rigid",
            "contact_duration_ccm", "contact_duration_rigid", "rebound_speed_ccm",
            "rebound_speed_rigid", "approach_speed", "error_peak_force", "error_indentation",
            "error_contact_duration", "error_rebound_speed"})
        c.exec(std::string("ALTER TABLE metrics DROP COLUMN ") + column);
    }
    const auto before = snapshot(db.parent_path());
    const auto r = test::run_ccm(status_of(db), dir);
    INFO(r.err);
    CHECK(r.status == 0);
    CHECK_THAT(r.out, Catch::Contains("modelling choices not recorded"));
    CHECK(snapshot(db.parent_path()) == before);
    db::Connection c(db);
    CHECK(db::schema_version(c) == 4);
  }
}

TEST_CASE("ccm study status --json gives every point's state and runs, and the totals",
          "[cli][store]") {
  test::TempDir dir;
  const fs::path db = synthetic_store(dir, "s.sqlite");
  const auto r = test::run_ccm(status_of(db) + " --json", dir);
  INFO(r.err);
  REQUIRE(r.status == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  db::StudyStore store(db, db::Access::read_only);
  REQUIRE(store.open_existing_study());
  const auto status = store.status();
  CHECK(j["db"] == db.string());
  CHECK(j["study"] == store.study_name());
  REQUIRE(j["points"].size() == status.size());
  std::map<std::string, int> totals;
  for (std::size_t k = 0; k < status.size(); ++k) {
    const nlohmann::json& p = j["points"][k];
    CHECK(p["index"] == status[k].point.index);
    CHECK(p["er"].get<double>() == status[k].point.modulus_ratio);
    CHECK(p["state"] == std::string(db::to_string(status[k].state)));
    CHECK(p["ccm"] == std::string(db::to_string(*status[k].ccm)));
    ++totals[p["state"]];
  }
  CHECK(j["totals"] == nlohmann::json(totals));
  CHECK(j["totals"]["unstable"] == 1);  // the synthetic study's one unstable point
  CHECK(j["modelling_choices"]["recorded"] == false);
}

TEST_CASE(
    "a store renamed or moved together with its histories folder still reads and "
    "reports, and a lost folder is named",
    "[cli][store]") {
  test::TempDir dir;
  const fs::path original = synthetic_store(dir, "default-study.sqlite");
  REQUIRE(fs::is_directory(dir.path / "stores" / "default-study.histories"));
  const auto first = [](const fs::path& db) {
    db::StudyStore store(db, db::Access::read_only);
    REQUIRE(store.open_existing_study());
    return store.load_run(kFirstPoint, study::ImpactModel::ccm);
  };
  const auto expected = first(original);
  REQUIRE(expected.has_value());

  SECTION("renamed and moved, with its folder renamed alike") {
    const fs::path elsewhere = dir.path / "archive";
    fs::create_directories(elsewhere);
    fs::rename(original, elsewhere / "trade-2026.sqlite");
    fs::rename(dir.path / "stores" / "default-study.histories", elsewhere / "trade-2026.histories");
    const auto moved = first(elsewhere / "trade-2026.sqlite");
    REQUIRE(moved.has_value());
    CHECK(moved->artifact.u_mean == expected->artifact.u_mean);
    const auto r = test::run_ccm("report --db '" + (elsewhere / "trade-2026.sqlite").string() +
                                     "' --out '" + (dir.path / "report").string() + "'",
                                 dir);
    INFO(r.err);
    CHECK(r.status == 0);
    CHECK(fs::exists(dir.path / "report" / "index.html"));
  }
  SECTION("renamed alone: the histories are found where they were written") {
    fs::rename(original, dir.path / "stores" / "renamed.sqlite");
    const auto renamed = first(dir.path / "stores" / "renamed.sqlite");
    REQUIRE(renamed.has_value());
    CHECK(renamed->artifact.kinetic_energy == expected->artifact.kinetic_energy);
  }
  SECTION("moved without its folder: the error names both places looked in") {
    fs::rename(original, dir.path / "lost.sqlite");
    const auto r = test::run_ccm("report --db '" + (dir.path / "lost.sqlite").string() +
                                     "' --out '" + (dir.path / "report").string() + "'",
                                 dir);
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains("is in neither " + (dir.path / "lost.histories").string()));
    CHECK_THAT(r.err, Catch::Contains((dir.path / "default-study.histories").string()));
    CHECK_FALSE(fs::exists(dir.path / "report"));
  }
}

}  // namespace ccm
