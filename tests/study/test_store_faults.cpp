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
#include <chrono>
#include <csignal>
#include <fstream>
#include <random>
#include <sstream>
#include <thread>

#include "db/sqlite/connection.hpp"
#include "db/sqlite/statement.hpp"
#include "db/store/study_store.hpp"
#include "tests/study/grid/grid_fixtures.hpp"
#include "tests/support/temp_dir.hpp"

using namespace ccm;
namespace fs = std::filesystem;

namespace {

const std::string kFaultGrid = test::tiny_study_grid();

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

// 10 x 10 x 5 points x 2 models of the tiny bodies: 1,000 runs in a few seconds.
std::string thousand_run_grid() {
  std::string text = kFaultGrid;
  text.replace(text.find("ER = [1.0, 100.0]"), 17,
               "ER = [1.0, 1.5, 2.0, 3.0, 5.0, 7.0, 10.0, 15.0, 20.0, 30.0]");
  text.replace(text.find("RLS = [0.5]"), 11,
               "RLS = [0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.1, 1.2, 1.3, 1.4]");
  text.replace(text.find("KE = [0.001]"), 12, "KE = [0.001, 0.002, 0.003, 0.004, 0.005]");
  return text;
}

// Starts `sh -c command` as a child process (to be killed or waited for).
pid_t spawn_shell(const std::string& command) {
  const pid_t pid = fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  return pid;
}

// The two stores' metrics are the same, point by point, bit for bit (deterministic runs).
void require_same_metrics(const fs::path& a_file, const fs::path& b_file) {
  db::StudyStore a(a_file, db::Access::read_only), b(b_file, db::Access::read_only);
  REQUIRE(a.open_existing_study());
  REQUIRE(b.open_existing_study());
  const auto metrics_a = a.load_metrics(), metrics_b = b.load_metrics();
  REQUIRE(metrics_a.size() == metrics_b.size());
  for (std::size_t i = 0; i < metrics_a.size(); ++i) {
    CHECK(metrics_a[i].final_state.u_mean == metrics_b[i].final_state.u_mean);
    CHECK(metrics_a[i].final_state.kinetic_energy == metrics_b[i].final_state.kinetic_energy);
  }
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
  require_same_metrics(whole, db);
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

namespace {

// How many rows the runs table holds, and how many share a point and a model (duplicates).
std::pair<long, long> run_rows(const fs::path& db) {
  db::Connection c(db, db::Access::read_only);
  db::Statement all(c, "SELECT COUNT(*) FROM runs");
  REQUIRE(all.step());
  db::Statement twice(c,
                      "SELECT COUNT(*) FROM (SELECT grid_point_id, model FROM runs GROUP BY "
                      "grid_point_id, model HAVING COUNT(*) > 1)");
  REQUIRE(twice.step());
  return {all.column_int(0), twice.column_int(0)};
}

}  // namespace

TEST_CASE("kill -9 at 50 random moments: the store stays whole and the study resumes to the end",
          "[study][cli][validation]") {
  test::TempDir tmp;
  // 16 points x 2 models of the tiny bodies, each run a fraction of a second.
  std::string text = kFaultGrid;
  text.replace(text.find("ER = [1.0, 100.0]"), 17, "ER = [1.0, 10.0, 100.0, 1000.0]");
  text.replace(text.find("RLS = [0.5]"), 11, "RLS = [0.5, 1.0]");
  text.replace(text.find("KE = [0.001]"), 12, "KE = [0.001, 0.01]");
  const fs::path grid = tmp.write("soak.toml", text);
  const fs::path reference = tmp.path / "reference.sqlite";
  REQUIRE(run_study(tmp, grid, reference).exit_code == 0);
  REQUIRE(run_states(reference)["completed"] == 32);

  std::mt19937 random(20261206);  // the moments are random, the test repeatable
  std::uniform_int_distribution<int> delay_ms(0, 250);  // the study takes ~0.3 s
  int store_number = 0, kills = 0, finished_stores = 0;
  fs::path db;
  int completed_before = 0;
  while (kills < 50) {
    if (db.empty() || (fs::exists(db) && run_states(db)["completed"] == 32)) {  // a fresh store
      if (!db.empty()) ++finished_stores;
      db = tmp.path / fmt::format("soak{}.sqlite", store_number++);
      completed_before = 0;
    }
    const std::string command =
        fmt::format("exec '{}' study run '{}' --db '{}' --quiet > /dev/null 2>&1", CCM_BINARY,
                    grid.string(), db.string());
    const pid_t pid = spawn_shell(command);
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms(random)));
    kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    ++kills;
    if (!fs::exists(db)) continue;  // killed before it made the store
    INFO("kill " << kills << " on " << db.filename().string());
    REQUIRE(integrity(db) == "ok");
    const auto [rows, duplicated] = run_rows(db);
    CHECK(duplicated == 0);
    CHECK(rows <= 32);
    const int completed = run_states(db)["completed"];
    CHECK(completed >= completed_before);  // no completed run lost
    completed_before = completed;
  }
  // The last store resumed to the end equals the uninterrupted study.
  REQUIRE(run_study(tmp, grid, db).exit_code == 0);
  CHECK(run_states(db)["completed"] == 32);
  CHECK(run_rows(db).second == 0);
  require_same_metrics(reference, db);
  WARN(kills << " kills over " << store_number << " stores, " << finished_stores
             << " of them finished between kills");
}

TEST_CASE("ccm study status reads a store while a study writes it", "[study][cli]") {
  test::TempDir tmp;
  std::string text = kFaultGrid;
  text.replace(text.find("ER = [1.0, 100.0]"), 17,
               "ER = [1.0, 3.0, 10.0, 30.0, 100.0, 300.0, 1000.0, 3000.0]");
  text.replace(text.find("RLS = [0.5]"), 11, "RLS = [0.5, 0.75, 1.0, 1.25]");
  const fs::path grid = tmp.write("busy.toml", text), db = tmp.path / "busy.sqlite";
  const std::string command = fmt::format("exec '{}' study run '{}' --db '{}' --quiet > /dev/null",
                                          CCM_BINARY, grid.string(), db.string());
  const pid_t pid = spawn_shell(command);
  int reads_during = 0, status = 0;
  while (waitpid(pid, &status, WNOHANG) == 0) {
    if (!fs::exists(db)) continue;
    const fs::path err = tmp.path / "status-err.txt";
    const int code = std::system(fmt::format("'{}' study status --db '{}' > /dev/null 2> '{}'",
                                             CCM_BINARY, db.string(), err.string())
                                     .c_str());
    const std::string message = text_of(err);
    // A store made a moment ago may not hold its study yet; anything else must read.
    if (message.find("holds no study yet") != std::string::npos) continue;
    INFO(message);
    CHECK(WEXITSTATUS(code) == 0);
    ++reads_during;
  }
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(run_states(db)["completed"] == 64);
  CHECK(reads_during >= 1);  // a loaded machine may read only once in the study's half second
}

namespace {

// The resident set of a process and its children, in kB (0 once it has exited).
long resident_kb(pid_t pid) {
  long total = 0;
  std::ifstream status(fmt::format("/proc/{}/status", pid));
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmRSS:", 0) == 0) total += std::stol(line.substr(6));
  std::ifstream children(fmt::format("/proc/{}/task/{}/children", pid, pid));
  for (pid_t child; children >> child;) total += resident_kb(child);
  return total;
}

long completed_rows(const fs::path& db) {
  try {
    db::Connection c(db, db::Access::read_only);
    db::Statement s(c, "SELECT COUNT(*) FROM runs WHERE status = 'completed'");
    return s.step() ? s.column_int(0) : 0;
  } catch (const db::StoreError&) {
    return 0;  // not made yet
  }
}

}  // namespace

TEST_CASE("a study of 1000 small runs holds its memory flat at a few ms of overhead per run",
          "[study][cli][validation]") {
  test::TempDir tmp;
  const std::string text = thousand_run_grid();
  const fs::path grid = tmp.write("long.toml", text), db = tmp.path / "long.sqlite";
  const std::string command = fmt::format("exec '{}' study run '{}' --db '{}' --quiet > /dev/null",
                                          CCM_BINARY, grid.string(), db.string());
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = spawn_shell(command);
  // The largest resident set seen while the first 100 runs, and the last 100, were under way.
  long first_peak = 0, last_peak = 0;
  int status = 0;
  while (waitpid(pid, &status, WNOHANG) == 0) {
    const long rss = resident_kb(pid), done = completed_rows(db);
    if (done < 100) first_peak = std::max(first_peak, rss);
    if (done >= 900 && done < 1000) last_peak = std::max(last_peak, rss);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  REQUIRE(WIFEXITED(status));
  REQUIRE(WEXITSTATUS(status) == 0);
  db::Connection c(db, db::Access::read_only);
  db::Statement runs(c, "SELECT COUNT(*), SUM(wall_seconds) FROM runs WHERE status = 'completed'");
  REQUIRE(runs.step());
  REQUIRE(runs.column_int(0) == 1000);
  // Everything but the runs' own step loops, per run: start-up, meshing, the store's writes and
  // the study's fits at the end, all charged to the runs.
  const double overhead = (wall - runs.column_double(1)) / 1000.0;
  INFO("first 100 runs: " << first_peak << " kB, last 100: " << last_peak << " kB; overhead "
                          << overhead * 1e3 << " ms per run over " << wall << " s");
  REQUIRE(first_peak > 0);
  REQUIRE(last_peak > 0);
  CHECK(static_cast<double>(last_peak) <= 1.10 * static_cast<double>(first_peak));
  CHECK(overhead < 0.050);
  WARN("first 100 runs " << first_peak << " kB, last 100 " << last_peak << " kB; overhead "
                         << overhead * 1e3 << " ms per run (" << wall << " s in all)");
}

TEST_CASE("ccm report and recommend read a store while a 1000-run study writes it",
          "[study][cli][validation]") {
  test::TempDir tmp;
  const std::string text = thousand_run_grid();
  const fs::path grid = tmp.write("busy.toml", text), db = tmp.path / "busy.sqlite";
  const pid_t pid =
      spawn_shell(fmt::format("exec '{}' study run '{}' --db '{}' --quiet > /dev/null", CCM_BINARY,
                              grid.string(), db.string()));
  // What a reading command may say of a store caught early: nothing to read yet. Anything else
  // but an answer is a failure.
  const auto not_yet = [](const std::string& err) {
    for (const char* early : {"holds no study yet", "no grid points yet",
                              "no completed or unstable", "no fits", "no fit"})
      if (err.find(early) != std::string::npos) return true;
    return false;
  };
  int reports = 0, recommendations = 0, status = 0;
  for (int k = 0; waitpid(pid, &status, WNOHANG) == 0; ++k) {
    if (!fs::exists(db)) continue;
    const fs::path err = tmp.path / "err.txt";
    const std::string command =
        k % 2 == 0 ? fmt::format("'{}' report --db '{}' --out '{}'", CCM_BINARY, db.string(),
                                 (tmp.path / fmt::format("report{}", k)).string())
                   : fmt::format("'{}' recommend --db '{}' --er 5 --rls 0.8 --ke 0.003", CCM_BINARY,
                                 db.string());
    const int code =
        std::system(fmt::format("{} > /dev/null 2> '{}'", command, err.string()).c_str());
    const std::string message = text_of(err);
    INFO(command << ": " << message);
    if (WEXITSTATUS(code) == 2 && not_yet(message)) continue;
    CHECK(WEXITSTATUS(code) == 0);
    (k % 2 == 0 ? reports : recommendations) += WEXITSTATUS(code) == 0;
  }
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(reports + recommendations >= 1);
  WARN(reports << " reports and " << recommendations << " recommendations while the study wrote");
}
