// `ccm study run / status` and `ccm recommend` end to end on a tiny grid: resume after SIGKILL,
// parallel workers and MPI ranks giving the serial results, two writers on one file, bad input.
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <csignal>
#include <fstream>
#include <thread>

#include "db/store/study_store.hpp"
#include "study/grid/grid_expand.hpp"
#include "study/grid/grid_file.hpp"
#include "tests/study/grid/grid_fixtures.hpp"
#include "tests/support/temp_dir.hpp"

extern char** environ;

using namespace ccm;
namespace fs = std::filesystem;

namespace {

const std::string kTinyGrid = test::tiny_study_grid();

std::string read_file(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs a shell command; returns its exit code, stderr into `err`.
int shell(const std::string& command, const fs::path& err_file, std::string& err) {
  const int status = std::system(fmt::format("{} 2> '{}'", command, err_file.string()).c_str());
  err = read_file(err_file);
  REQUIRE(WIFEXITED(status));
  return WEXITSTATUS(status);
}

std::string study_run(const fs::path& grid, const fs::path& db, const std::string& extra = "") {
  return fmt::format("'{}' study run '{}' --db '{}' --quiet {} > /dev/null", CCM_BINARY,
                     grid.string(), db.string(), extra);
}

// Every stored run's artifact histories, in point and model order.
std::vector<study::ArtifactHistory> stored_histories(const fs::path& db, const fs::path& grid) {
  db::StudyStore store(db);
  REQUIRE(store.open_existing_study());
  std::vector<study::ArtifactHistory> out;
  for (const auto& p : study::expand_grid(study::parse_grid_file(grid)))
    for (auto m : {study::ImpactModel::ccm, study::ImpactModel::rigid}) {
      const auto run = store.load_run(p, m);
      REQUIRE(run.has_value());
      out.push_back(run->artifact);
    }
  return out;
}

void require_same_histories(const std::vector<study::ArtifactHistory>& a,
                            const std::vector<study::ArtifactHistory>& b) {
  REQUIRE(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {  // deterministic runs: bit-identical
    CHECK(a[i].time == b[i].time);
    CHECK(a[i].u_mean == b[i].u_mean);
    CHECK(a[i].u_max == b[i].u_max);
    CHECK(a[i].kinetic_energy == b[i].kinetic_energy);
  }
}

long count_runs(const fs::path& db, std::optional<db::RunStatus> status) {
  db::StudyStore store(db);
  if (!store.open_existing_study()) return 0;
  long n = 0;
  for (const auto& s : store.status())
    for (const auto& run : {s.ccm, s.rigid})
      if (run && (!status || *run == *status)) ++n;
  return n;
}

}  // namespace

TEST_CASE("ccm study run: a serial study completes, resumes without rerunning, reports status",
          "[study][cli]") {
  test::TempDir tmp;
  const fs::path grid = tmp.write("tiny.toml", kTinyGrid), db = tmp.path / "s.sqlite";
  std::string err;
  REQUIRE(shell(study_run(grid, db), tmp.path / "err", err) == 0);
  CHECK(count_runs(db, db::RunStatus::completed) == 4);
  const auto first = stored_histories(db, grid);
  REQUIRE(first[0].time.size() == 31);  // 0 ... 30 ms every 1 ms

  // Again: nothing left to run, the same results.
  REQUIRE(shell(study_run(grid, db), tmp.path / "err", err) == 0);
  require_same_histories(first, stored_histories(db, grid));
  CHECK(count_runs(db, std::nullopt) == 4);

  std::string out = tmp.path / "status.txt";
  REQUIRE(shell(fmt::format("'{}' study status --db '{}' > '{}'", CCM_BINARY, db.string(), out),
                tmp.path / "err", err) == 0);
  CHECK_THAT(read_file(out), Catch::Contains("2 points: 2 done"));
  // The modelling choices, from the grid file the store keeps.
  CHECK_THAT(read_file(out), Catch::Contains("modelling choices (grid file " + grid.string()));
  CHECK_THAT(read_file(out), Catch::Contains("rigid penalty K_P per quadrature point: 1e+06 N/m"));
  CHECK_THAT(read_file(out), Catch::Contains("impactor mesh size / D_I: 0.5"));

  const std::string rec = (tmp.path / "rec.json").string();
  REQUIRE(shell(fmt::format("'{}' recommend --db '{}' --er 10 --rls 0.5 --ke 0.001 --json > '{}'",
                            CCM_BINARY, db.string(), rec),
                tmp.path / "err", err) == 0);
  const std::string json = read_file(rec);
  for (const char* field : {"\"model\"", "\"rule\"", "\"reliable\"", "\"unreliable_reasons\"",
                            "\"nearest_measured_points\"", "\"modelling_choices\"",
                            "\"rigid_penalty\"", "\"dcr_restitution\"", "\"clamped\""})
    CHECK_THAT(json, Catch::Contains(field));
  CHECK_THAT(json, Catch::Contains("\"value\": 1000000.0"));  // K_P of the grid
  CHECK_THAT(json, Catch::Contains("\"impact_errors\": {") &&
                       Catch::Contains("\"contact_duration\":"));  // the designer's errors

  const std::string text = (tmp.path / "rec.txt").string();
  REQUIRE(shell(fmt::format("'{}' recommend --db '{}' --er 1 --rls 0.5 --ke 0.001 > '{}'",
                            CCM_BINARY, db.string(), text),
                tmp.path / "err", err) == 0);
  CHECK_THAT(read_file(text), Catch::Contains("rule: use the rigid model where"));
  CHECK_THAT(read_file(text),
             Catch::Contains("point 0: ER 1, RLS 0.5, KE 0.001 J (distance 0.00)"));
  CHECK_THAT(read_file(text), Catch::Contains("rigid damping zeta (fraction of critical): 0"));
  CHECK_THAT(read_file(text), Catch::Contains("designer's errors (docs/metrics.md): peak force"));

  // Without --db: the reference store in ccm's data folder (here the tiny study, copied there),
  // named in the answer; without one there, bad input naming where it looked.
  const fs::path data = tmp.path / "data";
  fs::create_directories(data / "rig");
  fs::create_directories(data / "reference");
  fs::copy_file(fs::path(CCM_SOURCE_DIR) / "rig_models/cases.toml", data / "rig/cases.toml");
  fs::copy_file(db, data / "reference/whole-impacts.sqlite");
  const std::string histories = db.stem().string() + ".histories";  // as the store names it
  fs::copy(db.parent_path() / histories, data / "reference" / histories,
           fs::copy_options::recursive);
  const std::string reference_rec = fmt::format(
      "CCM_DATA_DIR='{}' '{}' recommend --er 10 --rls 0.5 --ke 0.001", data.string(), CCM_BINARY);
  REQUIRE(shell(reference_rec + " > '" + text + "'", tmp.path / "err", err) == 0);
  CHECK_THAT(read_file(text), Catch::Contains("whole-impacts.sqlite (study \"tiny\", the "
                                              "reference store ccm ships)"));
  REQUIRE(shell(reference_rec + " --json > '" + rec + "'", tmp.path / "err", err) == 0);
  CHECK_THAT(read_file(rec), Catch::Contains("\"reference\": true"));
  fs::remove(data / "reference/whole-impacts.sqlite");
  CHECK(shell(reference_rec, tmp.path / "err", err) == 2);
  CHECK_THAT(err, Catch::Contains("no --db given and no reference store at"));

  // The study has no other axis: naming one is bad input.
  CHECK(shell(fmt::format("'{}' recommend --db '{}' --er 1 --rls 0.5 --ke 0.001 --axis damping=1",
                          CCM_BINARY, db.string()),
              tmp.path / "err", err) == 2);
  CHECK_THAT(err, Catch::Contains("--axis damping: the study has no such axis"));
  CHECK(shell(fmt::format("'{}' recommend --db '{}' --er 1 --rls 0.5 --ke 0.001 --axis damping",
                          CCM_BINARY, db.string()),
              tmp.path / "err", err) == 2);
  CHECK_THAT(err, Catch::Contains("--axis damping: expected NAME=VALUE"));
}

TEST_CASE("ccm study run: killed with SIGKILL mid-study, it resumes to the uninterrupted result",
          "[study][cli]") {
  test::TempDir tmp;
  const fs::path grid = tmp.write("tiny.toml", kTinyGrid);
  const fs::path reference = tmp.path / "ref.sqlite", killed = tmp.path / "killed.sqlite";
  std::string err;
  REQUIRE(shell(study_run(grid, reference), tmp.path / "err", err) == 0);

  // Start a study, wait for its first committed run, kill it at once (the next run is then
  // under way: its row says "running"). On a loaded machine the study can finish its last run
  // before the kill lands: then the kill is tried again on a fresh store (at most 5 times).
  std::string bin = CCM_BINARY, g = grid.string(), d = killed.string();
  std::vector<char*> argv = {bin.data(),
                             const_cast<char*>("study"),
                             const_cast<char*>("run"),
                             const_cast<char*>(g.c_str()),
                             const_cast<char*>("--db"),
                             const_cast<char*>(d.c_str()),
                             const_cast<char*>("--quiet"),
                             nullptr};
  long done_before = 0;
  for (int attempt = 0; attempt < 5; ++attempt) {
    for (const char* suffix : {"", "-wal", "-shm", "-journal"}) fs::remove(d + suffix);
    pid_t pid = 0;
    REQUIRE(posix_spawn(&pid, bin.c_str(), nullptr, nullptr, argv.data(), environ) == 0);
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (count_runs(killed, db::RunStatus::completed) < 1 &&
           std::chrono::steady_clock::now() < give_up)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    REQUIRE(WIFSIGNALED(status));  // it was killed, not finished
    done_before = count_runs(killed, db::RunStatus::completed);
    if (done_before < 4) break;
  }
  CHECK(done_before >= 1);
  CHECK(done_before < 4);

  REQUIRE(shell(study_run(grid, killed), tmp.path / "err", err) == 0);
  CHECK(count_runs(killed, std::nullopt) == 4);  // one row per run: no duplicates
  CHECK(count_runs(killed, db::RunStatus::completed) == 4);
  require_same_histories(stored_histories(reference, grid), stored_histories(killed, grid));
}

TEST_CASE("ccm study run: --jobs 2 and two concurrent studies on one file give the serial result",
          "[study][cli]") {
  test::TempDir tmp;
  const fs::path grid = tmp.write("tiny.toml", kTinyGrid);
  const fs::path serial = tmp.path / "serial.sqlite", jobs = tmp.path / "jobs.sqlite",
                 shared = tmp.path / "shared.sqlite";
  std::string err;
  REQUIRE(shell(study_run(grid, serial), tmp.path / "err", err) == 0);
  REQUIRE(shell(study_run(grid, jobs, "--jobs 2"), tmp.path / "err", err) == 0);
  require_same_histories(stored_histories(serial, grid), stored_histories(jobs, grid));

  // Two studies on one file at once: both succeed, each run stored once.
  const std::string both =
      fmt::format("({} & {} ; wait)", study_run(grid, shared), study_run(grid, shared));
  REQUIRE(shell(fmt::format("sh -c \"{}\"", both), tmp.path / "err", err) == 0);
  CHECK(count_runs(shared, std::nullopt) == 4);
  require_same_histories(stored_histories(serial, grid), stored_histories(shared, grid));
}

TEST_CASE("ccm study run under mpirun -np 2 gives the serial result", "[study][cli][mpi]") {
  // The set-up installs Open MPI (docs/build.md): without mpirun this test fails, never skips.
  REQUIRE(std::system("command -v mpirun > /dev/null 2>&1") == 0);
  test::TempDir tmp;
  const fs::path grid = tmp.write("tiny.toml", kTinyGrid);
  const fs::path serial = tmp.path / "serial.sqlite", ranks = tmp.path / "ranks.sqlite";
  std::string err;
  REQUIRE(shell(study_run(grid, serial), tmp.path / "err", err) == 0);
  // Open MPI's own allocations are not ours to leak-check under the sanitizer build.
  const std::string mpi =
      fmt::format("ASAN_OPTIONS=detect_leaks=0 mpirun --allow-run-as-root --oversubscribe -np 2 {}",
                  study_run(grid, ranks));
  INFO(err);
  REQUIRE(shell(mpi, tmp.path / "err", err) == 0);
  require_same_histories(stored_histories(serial, grid), stored_histories(ranks, grid));
}

TEST_CASE("ccm study/recommend: bad input exits 2 with a clear message and writes nothing",
          "[study][cli]") {
  test::TempDir tmp;
  std::string err;
  const fs::path missing = tmp.path / "missing.sqlite";
  CHECK(shell(fmt::format("'{}' study status --db '{}'", CCM_BINARY, missing.string()),
              tmp.path / "err", err) == 2);
  CHECK(err == "ccm: error: " + missing.string() +
                   ": no such study database (run `ccm study run` first)\n");
  CHECK(!fs::exists(missing));

  const fs::path foreign = tmp.write("foreign.sqlite", "this is not a database\n");
  CHECK(shell(fmt::format("'{}' recommend --db '{}' --er 1 --rls 1 --ke 10", CCM_BINARY,
                          foreign.string()),
              tmp.path / "err", err) == 2);
  CHECK_THAT(err, Catch::StartsWith("ccm: error: " + foreign.string()));

  const fs::path bad_grid = tmp.write("bad.toml", "title = \"x\"\n[axes]\nER = [-1.0]\n");
  const fs::path db = tmp.path / "new.sqlite";
  CHECK(shell(study_run(bad_grid, db), tmp.path / "err", err) == 2);
  CHECK_THAT(err, Catch::StartsWith("ccm: error: " + bad_grid.string() + ":3"));
  CHECK(!fs::exists(db));  // nothing created for a grid that cannot run
}

TEST_CASE("ccm study scene: the printed scene, run alone, repeats the stored run", "[study][cli]") {
  test::TempDir tmp;
  const fs::path grid = tmp.write("tiny.toml", kTinyGrid), db = tmp.path / "s.sqlite";
  std::string err;
  REQUIRE(shell(study_run(grid, db), tmp.path / "err", err) == 0);
  const auto stored = stored_histories(db, grid);  // point 0 ccm, point 0 rigid, point 1 ...

  const fs::path scene = tmp.path / "p1_rigid.toml", out = tmp.path / "p1_rigid";
  REQUIRE(shell(fmt::format("'{}' study scene '{}' --point 1 --model rigid > '{}'", CCM_BINARY,
                            grid.string(), scene.string()),
                tmp.path / "err", err) == 0);
  CHECK_THAT(read_file(scene), Catch::Contains("model = \"rigid_penalty\""));
  REQUIRE(shell(fmt::format("'{}' run '{}' --out '{}' --quiet", CCM_BINARY, scene.string(),
                            out.string()),
                tmp.path / "err", err) == 0);

  // Column 1 of history.csv is the artifact's kinetic energy; same input, same output.
  std::ifstream csv(out / "history.csv");
  std::string line;
  std::getline(csv, line);
  REQUIRE_THAT(line, Catch::StartsWith("time,artifact.kinetic_energy,"));
  std::vector<double> ke;
  while (std::getline(csv, line)) ke.push_back(std::stod(line.substr(line.find(',') + 1)));
  const study::ArtifactHistory& rigid_p1 = stored[3];
  REQUIRE(ke.size() == rigid_p1.kinetic_energy.size());
  for (std::size_t i = 0; i < ke.size(); ++i)  // 17 significant digits in the CSV
    CHECK(ke[i] == Approx(rigid_p1.kinetic_energy[i]).epsilon(1e-15).margin(1e-300));

  CHECK(shell(fmt::format("'{}' study scene '{}' --point 9", CCM_BINARY, grid.string()),
              tmp.path / "err", err) == 2);
  CHECK(err == "ccm: error: " + grid.string() + ": no point 9 (the grid has points 0 to 1)\n");
}

namespace {

std::string whole_impact_grid() { return test::whole_impact_grid("whole"); }
using test::kWholeImpactGuard;

double last_time(const study::RunRecord& r) { return r.artifact.time.back(); }

}  // namespace

TEST_CASE("ccm study run: whole impacts, a point's two runs end together after both separate",
          "[study][cli]") {
  test::TempDir tmp;
  const fs::path grid = tmp.write("whole.toml", whole_impact_grid()), db = tmp.path / "w.sqlite";
  std::string err;
  REQUIRE(shell(study_run(grid, db, "--jobs 2"), tmp.path / "err", err) == 0);
  const auto points = study::expand_grid(study::parse_grid_file(grid));
  std::vector<study::RunRecord> rigid_runs;
  {
    db::StudyStore store(db);
    REQUIRE(store.open_existing_study());
    for (const auto& p : points) {
      const auto c = store.load_run(p, study::ImpactModel::ccm);
      const auto r = store.load_run(p, study::ImpactModel::rigid);
      REQUIRE(c.has_value());
      REQUIRE(r.has_value());
      REQUIRE(c->completed());
      REQUIRE(r->completed());
      INFO("point " << p.index << ": ccm ends at " << last_time(*c) << " s, rigid at "
                    << last_time(*r) << " s");
      CHECK(last_time(*c) == last_time(*r));  // common sample times: one final state
      CHECK(c->artifact.time == r->artifact.time);
      // Ended by separation, after the first touch (t_c = 20 ms) plus the hold, before the guard.
      CHECK(last_time(*c) > 0.02 + 0.005);
      CHECK(last_time(*c) < kWholeImpactGuard);
      // The impactor's centre-of-mass velocity at the same samples, and its mass: the point
      // scene gives the meshed sphere the analytic sphere's mass (rho pi D^3 / 6).
      for (const auto* run : {&*c, &*r}) {
        CHECK(run->impactor.vz.size() == run->artifact.time.size());
        CHECK(run->impactor.vz.front() < 0.0);  // it approaches along -z
      }
      CHECK(c->impactor.mass == Approx(1000.0 * M_PI / 6.0 * 0.125).epsilon(1e-9));
      CHECK(r->impactor.mass == Approx(c->impactor.mass).epsilon(1e-9));
      rigid_runs.push_back(*r);
    }
    // The two points differ in ER alone: their rigid scenes are the same, their ends need not be
    // (each ends with its CCM partner), so each point has its own rigid run.
    CHECK(rigid_runs[0].reuses_point == std::nullopt);
    CHECK(rigid_runs[1].reuses_point == std::nullopt);

    // A rigid run that ends apart from its partner (as after a kill between the CCM run's record
    // and the rigid run's rerun) is redone on resume to the partner's end: bit for bit the run
    // the study made.
    study::RunRecord cut = rigid_runs[0];
    const std::size_t keep = cut.artifact.time.size() / 2;
    for (auto* series : {&cut.artifact.time, &cut.artifact.kinetic_energy, &cut.artifact.u_mean,
                         &cut.artifact.u_max})
      series->resize(keep);
    store.record_run(cut, db::current_provenance("test"));
  }
  REQUIRE(shell(study_run(grid, db), tmp.path / "err", err) == 0);
  db::StudyStore store(db);
  REQUIRE(store.open_existing_study());
  const auto redone = store.load_run(points[0], study::ImpactModel::rigid);
  REQUIRE(redone.has_value());
  CHECK(redone->artifact.time == rigid_runs[0].artifact.time);
  CHECK(redone->artifact.kinetic_energy == rigid_runs[0].artifact.kinetic_energy);
  CHECK(redone->artifact.u_mean == rigid_runs[0].artifact.u_mean);
  CHECK(redone->artifact.u_max == rigid_runs[0].artifact.u_max);

  // A guard below the impact's end: the runs end there, and the study says which points did.
  std::string short_grid = whole_impact_grid();
  short_grid.replace(short_grid.find("end = 0.4"), 9, "end = 0.1");
  const fs::path guarded = tmp.write("guarded.toml", short_grid);
  REQUIRE(shell(study_run(guarded, tmp.path / "g.sqlite"), tmp.path / "err", err) == 0);
  CHECK_THAT(err, Catch::Contains("whole impacts: 1 of 2 points reached the guard [time] end") &&
                      Catch::Contains("(points 0)"));
}
