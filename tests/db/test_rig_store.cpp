// The rig's results in the store (db/store/rig_store.hpp, schema step 3): a run with its
// comparison, spread and channels is written whole in one transaction and read back as written;
// a calibration references its before and after runs (a dangling reference writes nothing); an
// older (version 2) store is migrated; a foreign file is refused untouched.
#include <catch2/catch.hpp>
#include <fstream>

#include "db/schema/migrations.hpp"
#include "db/sqlite/statement.hpp"
#include "db/store/rig_reader.hpp"
#include "db/store/rig_store.hpp"
#include "records/provenance/version.hpp"
#include "tests/db/scratch_dir.hpp"
#include "tests/db/store_queries.hpp"
#include "tests/support/rig_comparison.hpp"

using namespace ccm;

namespace {

rig::MeasuredTrial trial(int n, double scale) {
  rig::MeasuredTrial m;
  m.trial = n;
  for (int k = 0; k <= 20; ++k) {
    const double t = 0.01 * k;
    m.impactor_velocity_mps.t.push_back(t);
    m.impactor_velocity_mps.value.push_back(scale * t);
    m.artifact_angle_deg.t.push_back(t);
    m.artifact_angle_deg.value.push_back(scale * t * t);
    m.pressure_kpa.t.push_back(t);
    m.pressure_kpa.value.push_back(k >= 5 && k <= 10 ? 10.0 * scale : 0.0);
  }
  return m;
}

const std::string kStamp("2026-01-01T00:00:00.000Z");

db::RigRunRecord record() {
  const std::vector<rig::MeasuredTrial> trials{trial(1, 1.0), trial(2, 1.1)};
  rig::RigChannels sim{trials[0].impactor_velocity_mps, trials[0].artifact_angle_deg,
                       trials[0].pressure_kpa};
  for (double& v : sim.pressure_kpa.value) v *= 1.5;
  db::RigRunRecord r;
  r.row.case_code = "RX025";
  r.row.drive = "open-loop";
  r.row.drive_trial = 2;
  r.row.parameters = "pin=exact";
  r.row.status = "completed";
  r.row.window_end = 0.2;
  r.row.n_elements = 3121;
  r.row.steps = 1000;
  r.row.dt_min = 4e-7;
  r.row.wall_seconds = 1.5;
  r.row.cases_hash = "cases0123456789ab";
  r.row.geometry_hash = "geometry01234567";
  r.row.started_at = r.row.ended_at = kStamp;
  r.trials = {1, 2};
  r.comparison = test::rig_comparison(trials, sim);
  r.measured = rig::measured_spread(trials, 1.0);
  r.channels = sim;
  for (const rig::MeasuredTrial& m : trials)
    r.measured_channels.push_back({m.impactor_velocity_mps, m.artifact_angle_deg, m.pressure_kpa});
  return r;
}

}  // namespace

TEST_CASE("rig store: a run is written whole and read back", "[db][rig-store]") {
  test::ScratchDir dir("rig-store");
  db::RigStore store(dir / "rig.sqlite");
  const db::RigRunRecord r = record();
  const long long id = store.record_run(r);
  db::Connection& c = store.connection();
  CHECK(test::count_rows(c, "SELECT count(*) FROM rig_runs") == 1);
  CHECK(test::count_rows(c, "SELECT count(*) FROM rig_channel_metrics") == 3 * 2);
  CHECK(test::count_rows(c, "SELECT count(*) FROM rig_contact") == 2);
  CHECK(test::count_rows(c, "SELECT count(*) FROM rig_channel_samples") == 3 * 21);
  db::Statement q(c,
                  "SELECT rmse, peak_simulated, peak_measured FROM rig_channel_metrics WHERE "
                  "run_id = ?1 AND channel = 'pressure' AND trial = 2");
  q.bind(1, id);
  REQUIRE(q.step());
  CHECK(q.column_double(0) == r.comparison->pressure.per_trial[1].rmse);
  CHECK(q.column_double(1) == r.comparison->pressure.per_trial[1].peak_simulated);
  CHECK(q.column_double(1) == Approx(15.0).epsilon(1e-3));  // 10 kPa x 1.5, low-passed
  CHECK(q.column_double(2) == Approx(11.0));
  db::Statement s(c,
                  "SELECT mean, std_dev, n FROM rig_channel_spread WHERE run_id = ?1 AND "
                  "channel = 'velocity' AND metric = 'measured_peak'");
  s.bind(1, id);
  REQUIRE(s.step());
  CHECK(s.column_double(0) == Approx(0.21));  // peaks 0.2 and 0.22
  CHECK(s.column_int(2) == 2);
  db::Statement p(c, "SELECT ccm_version, git_hash, host, pid, drive_trial FROM rig_runs");
  REQUIRE(p.step());
  CHECK(p.column_text(0) == std::string(ccm_version()));
  CHECK(p.column_text(1) == std::string(git_hash()));
  CHECK(!p.column_text(2).empty());
  CHECK(p.column_int(3) == static_cast<long long>(::getpid()));
  CHECK(p.column_int(4) == 2);
  CHECK(test::integrity_check(c) == "ok");
}

TEST_CASE("rig store: a run scored on some trials stores those by number, every trial's samples",
          "[db][rig-store]") {
  // Trial 2 drove the run and is left out of the scores: the per-trial rows are trial 1's alone
  // (under its own number), the measured samples are both trials', V_i in contact is stored.
  test::ScratchDir dir("rig-scored");
  db::RigStore store(dir / "rig.sqlite");
  db::RigRunRecord r = record();
  const std::vector<rig::MeasuredTrial> scored{trial(1, 1.0)};
  r.comparison = test::rig_comparison(scored, r.channels);
  REQUIRE(r.comparison->velocity_in_contact.rmse);
  const long long id = store.record_run(r);
  db::Connection& c = store.connection();
  CHECK(test::count_rows(c, "SELECT count(*) FROM rig_channel_metrics WHERE trial = 1") == 3);
  CHECK(test::count_rows(c, "SELECT count(*) FROM rig_channel_metrics WHERE trial = 2") == 0);
  CHECK(test::count_rows(c, "SELECT count(*) FROM rig_contact") == 1);
  CHECK(test::count_rows(c, "SELECT count(DISTINCT trial) FROM rig_measured_samples") == 2);
  CHECK(test::count_rows(c,
                         "SELECT count(*) FROM rig_channel_spread WHERE channel = 'velocity' "
                         "AND metric IN ('contact_window_rmse', 'contact_window_nrmse') AND "
                         "n = 1") == 2);
  const db::RigRunRecord b = db::load_rig_run(c, id).record;
  CHECK(b.trials == std::vector<int>{1, 2});
  REQUIRE(b.comparison);
  CHECK(b.comparison->trials == std::vector<int>{1});
  REQUIRE(b.comparison->velocity_in_contact.rmse);
  CHECK(b.comparison->velocity_in_contact.rmse->mean ==
        r.comparison->velocity_in_contact.rmse->mean);
  CHECK(b.measured->n_trials == 2);
}

TEST_CASE("rig store: a run reads back as written, the trials cut to the run window",
          "[db][rig-store]") {
  test::ScratchDir dir("rig-read");
  db::RigStore store(dir / "rig.sqlite");
  db::RigRunRecord r = record();
  r.row.window_start = 0.02;
  r.row.window_end = 0.15;  // samples 2 ... 15 of 0 ... 20
  r.row.max_energy_error = 0.01;
  const long long id = store.record_run(r);
  store.record_run(record());  // a later run of the same case and drive
  db::RigRunRecord cal = record();
  cal.row.purpose = "calibration";
  store.record_run(cal);
  db::Connection& c = store.connection();
  CHECK(test::count_rows(c, "SELECT count(*) FROM rig_measured_samples WHERE run_id = 1") ==
        3 * 2 * 14);
  const std::vector<long long> latest = db::latest_rig_run_ids(c);
  REQUIRE(latest.size() == 1);
  CHECK(latest[0] == id + 1);
  const db::StoredRigRun back = db::load_rig_run(c, id);
  CHECK(back.id == id);
  const db::RigRunRecord& b = back.record;
  CHECK(b.row.case_code == "RX025");
  CHECK(b.row.drive_trial == 2);
  CHECK(b.row.n_elements == 3121);
  CHECK(b.row.dt_min == 4e-7);
  CHECK_FALSE(b.row.dt_max.has_value());
  CHECK(b.row.max_energy_error == 0.01);
  CHECK(b.row.window_end == 0.15);
  CHECK(b.trials == std::vector<int>{1, 2});
  CHECK(b.channels.pressure_kpa.value == r.channels.pressure_kpa.value);
  CHECK(b.channels.artifact_angle_deg.t == r.channels.artifact_angle_deg.t);
  REQUIRE(b.measured_channels.size() == 2);
  const rig::TimeSeries& v2 = b.measured_channels[1].impactor_velocity_mps;
  REQUIRE(v2.t.size() == 14);
  CHECK(v2.t.front() == 0.02);
  CHECK(v2.value.back() == r.measured_channels[1].impactor_velocity_mps.value[15]);
  REQUIRE(b.comparison);
  CHECK(b.comparison->pressure.per_trial.size() == 2);
  CHECK(b.comparison->pressure.per_trial[1].rmse == r.comparison->pressure.per_trial[1].rmse);
  CHECK(b.comparison->velocity.rmse.mean == r.comparison->velocity.rmse.mean);
  REQUIRE(b.comparison->contact.size() == 2);
  CHECK(b.comparison->contact[0].onset_error == r.comparison->contact[0].onset_error);
  REQUIRE(b.comparison->onset_error);
  CHECK(b.comparison->onset_error->mean == r.comparison->onset_error->mean);
  REQUIRE(b.measured);
  CHECK(b.measured->velocity.peak.mean == r.measured->velocity.peak.mean);
  CHECK_THROWS_AS(db::load_rig_run(c, 999), db::StoreError);
}

TEST_CASE("rig store: a calibration refers to its runs, a dangling one writes nothing",
          "[db][rig-store]") {
  test::ScratchDir dir("rig-calibration");
  db::RigStore store(dir / "rig.sqlite");
  const long long before = store.record_run(record());
  const long long after = store.record_run(record());
  db::RigCalibrationRecord cal;
  cal.case_code = "FF025";
  cal.drive = "open-loop";
  cal.algorithm = "LN_BOBYQA";
  cal.objective_name = "mean nRMSE";
  cal.result = "MAXEVAL_REACHED";
  cal.evaluations = 2;
  cal.max_evaluations = 2;
  cal.before_run_id = before;
  cal.after_run_id = after;
  cal.objective_before = 0.5;
  cal.objective_after = 0.4;
  cal.parameters = {{"mu_s", 0.0, 1.0, 0.4, 0.35, std::nullopt, std::nullopt},
                    {"mu_k", 0.0, 1.0, 0.7, 0.6, std::nullopt, std::nullopt}};
  cal.history = {{"mu_s=0.4;mu_k=0.7", 0.5, "completed", 1.0},
                 {"mu_s=0.35;mu_k=0.6", 0.4, "completed", 1.1}};
  cal.started_at = cal.ended_at = kStamp;
  store.record_calibration(cal);
  db::Connection& c = store.connection();
  CHECK(test::count_rows(c, "SELECT count(*) FROM rig_calibrations") == 1);
  const std::vector<db::RigCalibrationRecord> back = db::load_rig_calibrations(c);
  REQUIRE(back.size() == 1);
  CHECK(back[0].after_run_id == after);
  CHECK(back[0].objective_after == 0.4);
  REQUIRE(back[0].parameters.size() == 2);
  CHECK(back[0].parameters[0].name == "mu_k");  // by name
  CHECK(back[0].parameters[0].final == 0.6);
  REQUIRE(back[0].history.size() == 2);
  CHECK(back[0].history[1].objective == 0.4);
  CHECK(test::count_rows(c, "SELECT count(*) FROM rig_calibration_parameters") == 2);
  CHECK(test::count_rows(c, "SELECT count(*) FROM rig_calibration_evaluations") == 2);
  cal.after_run_id = 999;  // no such run: the foreign key fails, the transaction rolls back
  CHECK_THROWS_AS(store.record_calibration(cal), db::StoreError);
  CHECK(test::count_rows(c, "SELECT count(*) FROM rig_calibrations") == 1);
  CHECK(test::count_rows(c, "SELECT count(*) FROM rig_calibration_parameters") == 2);
  cal.after_run_id = after;
  cal.parameters[0].final = 2.0;  // outside its bounds: CHECK constraint
  CHECK_THROWS_AS(store.record_calibration(cal), db::StoreError);
  CHECK(test::count_rows(c, "SELECT count(*) FROM rig_calibrations") == 1);
}

TEST_CASE("rig store: a version-2 store is migrated, a foreign file refused", "[db][rig-store]") {
  test::ScratchDir dir("rig-migrate");
  {
    db::Connection c(dir / "old.sqlite");
    db::migrate(c, 2);
    c.exec("INSERT INTO studies VALUES (1, 'old', 'g1', 'then', '0.0.9', 'abc')");
  }
  {
    db::RigStore store(dir / "old.sqlite");
    CHECK(db::schema_version(store.connection()) == db::latest_schema_version());
    CHECK(test::count_rows(store.connection(), "SELECT count(*) FROM studies") == 1);
    store.record_run(record());
  }
  const auto foreign = dir / "notes.sqlite";
  std::ofstream(foreign) << "not a database\n";
  CHECK_THROWS_WITH(db::RigStore(foreign), Catch::Contains("not a ccm study store"));
}
