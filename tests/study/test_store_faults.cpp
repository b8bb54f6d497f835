// The store under a full disk (issue: the store under faults): a study whose disk fills mid-run
// stops with a message that names the store and says how to go on, keeps every run it completed,
// leaves a store that passes SQLite's integrity check, and the same command resumes it to the
// uninterrupted result. The full disk is injected (tests/support/disk_full_preload.c): writes
// under the store's folder fail with ENOSPC once a budget of bytes is spent, placed at 60 % of
// what the whole study writes into a store that already has its schema.
#include <fmt/format.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>

#include "db/sqlite/connection.hpp"
#include "db/sqlite/statement.hpp"
#include "db/store/study_store.hpp"
#include "tests/study/grid/grid_fixtures.hpp"
#include "tests/support/temp_dir.hpp"

using namespace ccm;
namespace fs = std::filesystem;

namespace {

const std::string kFaultGrid = R"(title = "tiny"
[axes]
ER = [1.0, 100.0]
RLS = [0.5]
KE = [0.001]
[time]
contact_time = 0.02
end = 0.03
output_interval = 1e-3
)" + std::string(test::kTinyGridBodies);

std::string text_of(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

struct Outcome {
  int exit_code;
  std::string err;
};

// `ccm study run` on the grid into db, with `environment` ("NAME=value ...") in front.
Outcome run_study(const test::TempDir& tmp, const fs::path& grid, const fs::path& db,
                  const std::string& environment = "") {
  const fs::path err = tmp.path / "err.txt";
  const int status =
      std::system(fmt::format("{} '{}' study run '{}' --db '{}' --quiet > /dev/null 2> '{}'",
                              environment, CCM_BINARY, grid.string(), db.string(), err.string())
                      .c_str());
  REQUIRE(WIFEXITED(status));  // never a crash
  return {WEXITSTATUS(status), text_of(err)};
}

// Runs by status, over the study's points and both models.
std::map<std::string, int> run_states(const fs::path& db) {
  std::map<std::string, int> n;
  db::StudyStore store(db, db::Access::read_only);
  if (!store.open_existing_study()) return n;
  for (const auto& p : store.status())
    for (const auto& run : {p.ccm, p.rigid}) ++n[run ? std::string(db::to_string(*run)) : "none"];
  return n;
}

std::string integrity(const fs::path& db) {
  db::Connection c(db, db::Access::read_only);
  db::Statement s(c, "PRAGMA integrity_check");
  REQUIRE(s.step());
  return s.column_text(0);
}

}  // namespace

TEST_CASE("a study whose disk fills mid-run keeps its runs and resumes to the whole result",
          "[study][cli]") {
  test::TempDir tmp;
  const fs::path grid = tmp.write("tiny.toml", kFaultGrid);
  const fs::path folder = tmp.path / "disk";
  fs::create_directories(folder);
  const std::string preload = fmt::format(
      "LD_PRELOAD='{}' ASAN_OPTIONS=\"$ASAN_OPTIONS:verify_asan_link_order=0\" "
      "CCM_TEST_DISK_DIR='{}'",
      CCM_DISK_FULL_PRELOAD, fs::canonical(folder).string());

  // Each store made first, with its schema (most of an empty store's bytes): the fault then
  // falls among the runs, not in the migration.
  const auto make_store = [](const fs::path& file) { db::StudyStore store(file); };

  // The whole study, counting what it writes there.
  const fs::path report = tmp.path / "bytes.txt";
  const fs::path whole = folder / "whole.sqlite";
  make_store(whole);
  REQUIRE(run_study(tmp, grid, whole,
                    preload + fmt::format(" CCM_TEST_DISK_REPORT='{}'", report.string()))
              .exit_code == 0);
  unsigned long long bytes = 0;
  std::istringstream(text_of(report)) >> bytes;  // the first process: the study itself
  REQUIRE(bytes > 0);
  REQUIRE(run_states(whole)["completed"] == 4);

  // The same study on a disk that fills at 60 % of that.
  const fs::path db = folder / "full.sqlite";
  make_store(db);
  const Outcome full =
      run_study(tmp, grid, db, preload + fmt::format(" CCM_TEST_DISK_BYTES={}", bytes * 6 / 10));
  INFO(full.err);
  CHECK(full.exit_code == 2);
  CHECK_THAT(full.err, Catch::Contains("ccm: error: " + folder.string()));
  CHECK_THAT(full.err, Catch::Contains("the same command resumes the study"));
  CHECK(integrity(db) == "ok");
  const int kept = run_states(db)["completed"];
  CHECK(kept < 4);

  // Space again: the same command completes it, each run once, as the uninterrupted study.
  REQUIRE(run_study(tmp, grid, db).exit_code == 0);
  const auto after = run_states(db);
  CHECK(after.at("completed") == 4);
  CHECK(after.size() == 1);  // no other state, no duplicate
  CHECK(integrity(db) == "ok");
  db::StudyStore a(whole, db::Access::read_only), b(db, db::Access::read_only);
  REQUIRE(a.open_existing_study());
  REQUIRE(b.open_existing_study());
  const auto metrics_a = a.load_metrics(), metrics_b = b.load_metrics();
  REQUIRE(metrics_a.size() == metrics_b.size());
  for (std::size_t i = 0; i < metrics_a.size(); ++i)
    CHECK(metrics_a[i].final_state.u_mean == metrics_b[i].final_state.u_mean);
}

TEST_CASE("a read-only store or folder: writing commands say so and exit 2, reading ones read",
          "[study][cli]") {
  test::TempDir tmp;
  const fs::path grid = tmp.write("tiny.toml", kFaultGrid);
  const fs::path folder = tmp.path / "ro";
  fs::create_directories(folder);
  const fs::path db = folder / "s.sqlite";
  REQUIRE(run_study(tmp, grid, db).exit_code == 0);
  // As root every file is writable: the commands then run as the user nobody (setpriv, from
  // util-linux), who reads the test's folders and owns nothing in them.
  const bool root = geteuid() == 0;
  const std::string as_user = root ? "setpriv --reuid=65534 --regid=65534 --clear-groups" : "";
  using fs::perms;
  fs::permissions(tmp.path, perms::owner_all | perms::group_read | perms::group_exec |
                                perms::others_read | perms::others_exec);
  const fs::path writable_out = tmp.path / "out";
  fs::create_directories(writable_out);
  fs::permissions(writable_out, perms::all);
  // What the other user runs and reads lies in the test's folder: the build and the sources may
  // lie where only their owner may look (a clone under /root).
  const fs::path binary = writable_out / "ccm", supp = writable_out / "lsan.supp";
  fs::copy_file(CCM_BINARY, binary);
  fs::copy_file(fs::path(CCM_SOURCE_DIR) / "tests" / "lsan.supp", supp);
  const std::string environment = fmt::format("LSAN_OPTIONS=suppressions='{}' CCM_MESH_CACHE='{}'",
                                              supp.string(), (writable_out / "cache").string());
  const auto ccm_as_user = [&](const std::string& args) {
    const fs::path err = writable_out / "err.txt";
    const int status = std::system(fmt::format("{} {} '{}' {} > /dev/null 2> '{}'", environment,
                                               as_user, binary.string(), args, err.string())
                                       .c_str());
    REQUIRE(WIFEXITED(status));
    return Outcome{WEXITSTATUS(status), text_of(err)};
  };
  const perms read_only = perms::owner_read | perms::group_read | perms::others_read;
  const perms read_exec = read_only | perms::owner_exec | perms::group_exec | perms::others_exec;
  fs::permissions(db, read_only);
  fs::permissions(folder / "s.histories", read_exec);
  fs::permissions(folder, read_exec);
  const std::string db_arg = fmt::format("--db '{}'", db.string());

  const Outcome run = ccm_as_user(fmt::format("study run '{}' {} --quiet", grid.string(), db_arg));
  CHECK(run.exit_code == 2);
  CHECK_THAT(run.err, Catch::Contains(db.string() + ": the store is read-only"));
  const Outcome status = ccm_as_user("study status " + db_arg);
  CHECK(status.exit_code == 0);
  CHECK(status.err.empty());
  const Outcome report_there =
      ccm_as_user(fmt::format("report {} --out '{}'", db_arg, (folder / "report").string()));
  CHECK(report_there.exit_code == 2);
  CHECK_THAT(report_there.err, Catch::Contains("--out " + (folder / "report").string() + ": " +
                                               folder.string() + " is not writable"));
  CHECK_FALSE(fs::exists(folder / "report"));

  // The store writable, its folder not (SQLite could not make its journal beside it).
  if (root) CHECK(std::system(fmt::format("chown 65534 '{}'", db.string()).c_str()) == 0);
  fs::permissions(db,
                  perms::owner_read | perms::owner_write | perms::group_read | perms::others_read);
  const Outcome in_folder =
      ccm_as_user(fmt::format("study run '{}' {} --quiet", grid.string(), db_arg));
  CHECK(in_folder.exit_code == 2);
  CHECK_THAT(in_folder.err,
             Catch::Contains(db.string() + ": its folder " + folder.string() + " is not writable"));
  fs::permissions(folder, perms::owner_all);  // the temporary folder can be removed again
}
