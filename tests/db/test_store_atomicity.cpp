// Every run is committed atomically: a rolled-back, failed or killed transaction leaves no
// partial run; two processes writing one store at once both succeed.
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>

#include "db/store/point_key.hpp"
#include "db/store/study_store.hpp"
#include "study/metrics/point_metrics.hpp"
#include "tests/db/scratch_dir.hpp"
#include "tests/db/store_queries.hpp"
#include "tests/study/metrics/synthetic_runs.hpp"

using namespace ccm;
using study::ImpactModel;

namespace {

// Runs `body` in a child process and returns its exit status (the child never returns into
// Catch2: it leaves with _exit, like a killed process, skipping every destructor).
template <typename F>
pid_t spawn(F body) {
  const pid_t pid = fork();
  if (pid == 0) {
    int code = 0;
    try {
      code = body();
    } catch (...) {
      code = 2;
    }
    _exit(code);
  }
  return pid;
}

int wait_for(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

long long runs_in(const std::filesystem::path& file) {
  db::StudyStore store(file);
  return test::count_rows(store.connection(), "SELECT count(*) FROM runs");
}

}  // namespace

TEST_CASE("a rolled-back transaction leaves no run, no metrics and no grid point", "[db]") {
  test::ScratchDir dir("db-rollback");
  const auto file = dir / "s.sqlite";
  db::StudyStore store(file);
  store.open_study("s", "g");
  const auto prov = db::current_provenance("g");
  const auto c = test::synthetic_run(ImpactModel::ccm), r = test::synthetic_run(ImpactModel::rigid);
  {
    db::Transaction outer = store.begin();  // both runs and their metrics as one unit
    store.record_run(c, prov);
    store.record_run(r, prov);
    store.save_metrics(study::compute_point_metrics(c, r));
    CHECK(test::count_rows(store.connection(), "SELECT count(*) FROM runs") == 2);
    // ... an exception leaves the scope before outer.commit()
  }
  CHECK(test::count_rows(store.connection(), "SELECT count(*) FROM runs") == 0);
  CHECK(test::count_rows(store.connection(), "SELECT count(*) FROM metrics") == 0);
  CHECK(test::count_rows(store.connection(), "SELECT count(*) FROM grid_points") == 0);
  CHECK(store.status().empty());
  CHECK_FALSE(store.is_done(c.point, ImpactModel::ccm));
}

TEST_CASE("a run whose write fails half-way leaves nothing behind", "[db]") {
  test::ScratchDir dir("db-half");
  db::StudyStore store(dir / "s.sqlite");
  store.open_study("s", "g");
  auto prov = db::current_provenance("g");
  prov.host = "";  // violates CHECK(length(host) > 0) after the grid point row is written
  const auto run = test::synthetic_run(ImpactModel::ccm);
  CHECK_THROWS_AS(store.record_run(run, prov), db::StoreError);
  CHECK(test::count_rows(store.connection(), "SELECT count(*) FROM grid_points") == 0);
  CHECK(test::count_rows(store.connection(), "SELECT count(*) FROM runs") == 0);
  // The store is still usable for the next run.
  store.record_run(run, db::current_provenance("g"));
  CHECK(store.is_done(run.point, ImpactModel::ccm));
}

TEST_CASE("a process killed inside its transaction leaves no partial run", "[db]") {
  test::ScratchDir dir("db-killed");
  const auto file = dir / "s.sqlite";
  {
    db::StudyStore store(file);
    store.open_study("s", "g");
  }
  const auto run = test::synthetic_run(ImpactModel::ccm);
  const pid_t child = spawn([&] {
    db::StudyStore store(file);
    db::Transaction tx = store.begin();
    store.record_run(run, db::current_provenance("g"));
    _exit(0);  // dies with the transaction open: no commit, no rollback, no close
    return 0;
  });
  REQUIRE(wait_for(child) == 0);
  db::StudyStore store(file);
  CHECK(test::integrity_check(store.connection()) == "ok");
  CHECK(test::count_rows(store.connection(), "SELECT count(*) FROM runs") == 0);
  CHECK_FALSE(store.is_done(run.point, ImpactModel::ccm));
  // Its history file may exist, but nothing references it; the redone run succeeds.
  store.record_run(run, db::current_provenance("g"));
  CHECK(store.load_run(run.point, ImpactModel::ccm)->artifact.u_max == run.artifact.u_max);
}

TEST_CASE("two processes writing one store at once both succeed, without duplicates", "[db]") {
  test::ScratchDir dir("db-two-writers");
  const auto file = dir / "s.sqlite";
  {
    db::StudyStore store(file);
    store.open_study("s", "g");
  }
  constexpr int kPointsPerWriter = 15;
  auto writer = [&](int first) {
    return [&file, first] {
      db::StudyStore store(file);
      const auto prov = db::current_provenance("g", 1, 2);
      for (int i = first; i < first + kPointsPerWriter; ++i)
        for (const ImpactModel m : {ImpactModel::ccm, ImpactModel::rigid}) {
          study::RunRecord run = test::synthetic_run(m, i);
          run.point.modulus_ratio = 1.0 + i;
          if (!store.mark_running(run.point, m, prov, db::utc_now())) return 3;
          store.record_run(run, prov);
        }
      // Both also write one shared point: one of them replaces the other's row.
      store.record_run(test::synthetic_run(ImpactModel::ccm, 999), prov);
      return 0;
    };
  };
  const pid_t a = spawn(writer(0));
  const pid_t b = spawn(writer(kPointsPerWriter));
  CHECK(wait_for(a) == 0);
  CHECK(wait_for(b) == 0);
  db::StudyStore store(file);
  CHECK(test::integrity_check(store.connection()) == "ok");
  CHECK(runs_in(file) == 4 * kPointsPerWriter + 1);
  CHECK(test::count_rows(store.connection(),
                         "SELECT count(*) FROM runs WHERE status = 'completed'") ==
        4 * kPointsPerWriter + 1);
  CHECK(test::count_rows(store.connection(), "SELECT count(DISTINCT pid) FROM runs") == 2);
}

// A reader of a store without a -wal file reads without locks (db/sqlite/connection.cpp); a
// writer in rollback-journal mode (creating or migrating the store) writes the main file only
// while its -journal exists, so the reader waits for the journal to go.
TEST_CASE("a reader waits while a store's rollback journal is there", "[db]") {
  test::ScratchDir dir("db-journal-reader");
  const auto file = dir / "s.sqlite";
  {
    db::StudyStore store(file);
    store.open_study("s", "g");
  }
  REQUIRE_FALSE(std::filesystem::exists(file.string() + "-wal"));
  const std::filesystem::path journal = file.string() + "-journal";
  std::ofstream(journal) << "";
  std::thread writer([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    std::filesystem::remove(journal);
  });
  const auto t0 = std::chrono::steady_clock::now();
  const db::StudyStore reader(file, db::Access::read_only);
  const double waited =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  writer.join();
  CHECK(waited >= 0.25);
  CHECK(reader.study_name() == "s");
}
