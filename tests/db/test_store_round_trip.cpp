// Study store: runs, histories, metrics and fits come back as written; resume and status.
#include <catch2/catch.hpp>
#include <filesystem>

#include "db/history/history_file.hpp"
#include "db/schema/migrations.hpp"
#include "db/store/point_key.hpp"
#include "db/store/study_store.hpp"
#include "records/provenance/version.hpp"
#include "study/fit/study_fits.hpp"
#include "study/metrics/point_metrics.hpp"
#include "study/recommend/recommendation.hpp"
#include "tests/db/scratch_dir.hpp"
#include "tests/db/store_queries.hpp"
#include "tests/study/metrics/synthetic_runs.hpp"

using namespace ccm;
using study::ImpactModel;

namespace {

void check_same_run(const study::RunRecord& a, const study::RunRecord& b) {
  CHECK(a.point.index == b.point.index);
  CHECK(a.point.modulus_ratio == b.point.modulus_ratio);
  CHECK(a.point.other_axes == b.point.other_axes);
  CHECK(a.verdict == b.verdict);
  CHECK(a.reason == b.reason);
  CHECK(a.steps == b.steps);
  CHECK(a.wall_seconds == b.wall_seconds);
  CHECK(a.initial_stable_dt == b.initial_stable_dt);
  CHECK(a.average_iteration_seconds == b.average_iteration_seconds);
  CHECK(a.dt_min == b.dt_min);
  CHECK(a.max_energy_error == b.max_energy_error);
  CHECK(a.n_elements == b.n_elements);
  CHECK(a.scene_hash == b.scene_hash);
  CHECK(a.started_at == b.started_at);
  REQUIRE(a.cost.has_value() == b.cost.has_value());
  if (a.cost) {
    CHECK(a.cost->step_cpu_seconds == b.cost->step_cpu_seconds);
    CHECK(a.cost->step_wall_seconds == b.cost->step_wall_seconds);
    CHECK(a.cost->dt_first == b.cost->dt_first);
    CHECK(a.cost->dt_mean == b.cost->dt_mean);
    CHECK(a.cost->steps_structure == b.cost->steps_structure);
    CHECK(a.cost->steps_contact == b.cost->steps_contact);
    CHECK(a.cost->steps_max_dt == b.cost->steps_max_dt);
    CHECK(a.cost->steps_landing == b.cost->steps_landing);
    CHECK(a.cost->dt_contact_min == b.cost->dt_contact_min);
  }
  CHECK(a.reuses_point == b.reuses_point);
  CHECK(a.artifact.time == b.artifact.time);  // bit-exact through HDF5 (IEEE f64 LE)
  CHECK(a.artifact.u_mean == b.artifact.u_mean);
  CHECK(a.artifact.u_max == b.artifact.u_max);
  CHECK(a.artifact.kinetic_energy == b.artifact.kinetic_energy);
  CHECK(a.impactor.mass == b.impactor.mass);
  CHECK(a.impactor.vx == b.impactor.vx);
  CHECK(a.impactor.vy == b.impactor.vy);
  CHECK(a.impactor.vz == b.impactor.vz);
}

}  // namespace

TEST_CASE("runs and their HDF5 histories round-trip bit-exactly, with provenance", "[db]") {
  test::ScratchDir dir("db-round-trip");
  const auto prov = db::current_provenance("gridhash", 2, 3);
  const study::RunRecord ccm_run = test::synthetic_run(ImpactModel::ccm);
  {
    db::StudyStore store(dir / "study.sqlite");
    store.open_study("table-2.2", "gridhash");
    store.record_run(ccm_run, prov);
  }
  db::StudyStore store(dir / "study.sqlite");  // reopened: the study is found again
  CHECK(store.study_name() == "table-2.2");
  const auto loaded = store.load_run(ccm_run.point, ImpactModel::ccm);
  REQUIRE(loaded);
  check_same_run(*loaded, ccm_run);
  CHECK_FALSE(store.load_run(ccm_run.point, ImpactModel::rigid));
  // A run stored as a reuse of another point's run (same model and scene) says which; a run
  // with no contact-limited step has no smallest contact-limited step.
  study::RunRecord reused = test::synthetic_run(ImpactModel::ccm, 8);
  reused.point.modulus_ratio = 1.0;
  reused.reuses_point = ccm_run.point.index;
  REQUIRE_FALSE(reused.cost->dt_contact_min.has_value());
  store.record_run(reused, prov);
  const auto reused_back = store.load_run(reused.point, ImpactModel::ccm);
  REQUIRE(reused_back);
  check_same_run(*reused_back, reused);
  const auto rigid_run = test::synthetic_run(ImpactModel::rigid);
  REQUIRE(rigid_run.cost->dt_contact_min.has_value());
  store.record_run(rigid_run, prov);
  check_same_run(*store.load_run(rigid_run.point, ImpactModel::rigid), rigid_run);

  db::Statement row(
      store.connection(),
      "SELECT ccm_version, git_hash, grid_hash, host, pid, ranks, jobs, history_file, "
      "history_dataset, status FROM runs ORDER BY id");
  REQUIRE(row.step());
  CHECK(row.column_text(0) == std::string(ccm_version()));
  CHECK(row.column_text(1) == std::string(git_hash()));
  CHECK(row.column_text(2) == "gridhash");
  CHECK(row.column_text(3) == prov.host);
  CHECK(row.column_int(4) == prov.pid);
  CHECK(row.column_int(5) == 2);
  CHECK(row.column_int(6) == 3);
  CHECK(std::filesystem::exists(dir.path() / row.column_text(7)));
  CHECK(row.column_text(8) == "/artifact");
  CHECK(row.column_text(9) == "completed");
  CHECK(test::count_rows(store.connection(), "SELECT count(*) FROM grid_points") == 2);
  db::Statement mode(store.connection(), "PRAGMA journal_mode");
  mode.step();
  CHECK(mode.column_text(0) == "wal");
}

TEST_CASE("resume: an interrupted run is redone in place, a finished one is not", "[db]") {
  test::ScratchDir dir("db-resume");
  const auto prov = db::current_provenance("g");
  const study::RunRecord run = test::synthetic_run(ImpactModel::rigid);
  const std::string hash = db::grid_point_hash(run.point);
  {
    db::StudyStore store(dir / "s.sqlite");
    store.open_study("s", "g");
    CHECK_FALSE(store.run_status(hash, ImpactModel::rigid));
    CHECK(store.mark_running(run.point, ImpactModel::rigid, prov, db::utc_now()));
    // ... the process dies here: the row stays "running".
  }
  db::StudyStore store(dir / "s.sqlite");
  CHECK(store.run_status(hash, ImpactModel::rigid) == db::RunStatus::running);
  CHECK_FALSE(store.is_done(hash, ImpactModel::rigid));
  CHECK(store.status().at(0).state == db::PointState::running);
  CHECK(store.mark_running(run.point, ImpactModel::rigid, prov, db::utc_now()));
  store.record_run(run, prov);
  CHECK(store.is_done(run.point, ImpactModel::rigid));
  CHECK_FALSE(store.mark_running(run.point, ImpactModel::rigid, prov, db::utc_now()));
  CHECK(store.run_status(hash, ImpactModel::rigid) == db::RunStatus::completed);
  CHECK(test::count_rows(store.connection(), "SELECT count(*) FROM runs") == 1);
  // Recording the same run again replaces it: still one row (UNIQUE(grid_point_id, model)).
  store.record_run(run, prov);
  CHECK(test::count_rows(store.connection(), "SELECT count(*) FROM runs") == 1);
}

TEST_CASE("status: done, unstable, failed and pending points", "[db]") {
  test::ScratchDir dir("db-status");
  const auto prov = db::current_provenance("g");
  db::StudyStore store(dir / "s.sqlite");
  store.open_study("s", "g");
  for (int i = 0; i < 4; ++i) {
    study::RunRecord c = test::synthetic_run(ImpactModel::ccm, i);
    study::RunRecord r = test::synthetic_run(ImpactModel::rigid, i);
    c.point.modulus_ratio = r.point.modulus_ratio = std::pow(10.0, i);
    if (i == 1) {
      c.verdict = "unstable";
      c.reason = "inverted element 12";
    }
    if (i == 2) {
      store.record_failure(c.point, ImpactModel::ccm, "mesher: no volume", prov);
      continue;
    }
    store.record_run(r, prov);
    if (i != 3) store.record_run(c, prov);
  }
  const auto status = store.status();
  REQUIRE(status.size() == 4);
  CHECK(status[0].state == db::PointState::done);
  CHECK(status[1].state == db::PointState::unstable);
  CHECK(status[1].reason == "inverted element 12");
  CHECK(status[2].state == db::PointState::failed);
  CHECK(status[2].reason == "mesher: no volume");
  CHECK(status[3].state == db::PointState::pending);
  CHECK(status[3].rigid == db::RunStatus::completed);
  CHECK_FALSE(status[3].ccm);
  // An unstable result is final (deterministic); a failure is redone.
  CHECK(store.is_done(status[1].content_hash, ImpactModel::ccm));
  CHECK_FALSE(store.is_done(status[2].content_hash, ImpactModel::ccm));
}

TEST_CASE("metrics and fits round-trip, unusable points stay visible", "[db]") {
  test::ScratchDir dir("db-results");
  db::StudyStore store(dir / "s.sqlite");
  store.open_study("s", "g");
  std::vector<study::PointMetrics> points;
  int index = 0;
  for (const double er : {1.0, 1e2, 1e4, 1e6})
    for (const double rls : {0.5, 1.0, 1.5}) {
      study::RunRecord c = test::synthetic_run(ImpactModel::ccm, index);
      study::RunRecord r = test::synthetic_run(ImpactModel::rigid, index++);
      c.point.modulus_ratio = r.point.modulus_ratio = er;
      c.point.length_ratio = r.point.length_ratio = rls;
      c.artifact.u_max.back() = 3.0 + std::log10(er) * rls;  // vary the final-state error
      if (index == 5) c.verdict = "unstable";
      points.push_back(study::compute_point_metrics(c, r));
      store.save_metrics(points.back());
    }
  const auto loaded = store.load_metrics();
  REQUIRE(loaded.size() == points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    CHECK(loaded[i].usable == points[i].usable);
    CHECK(loaded[i].excluded_reason == points[i].excluded_reason);
    CHECK(loaded[i].final_state.u_max == points[i].final_state.u_max);
    CHECK(loaded[i].cumulative.kinetic_energy == points[i].cumulative.kinetic_energy);
    CHECK(loaded[i].weighting.u_max == points[i].weighting.u_max);
    CHECK(loaded[i].runtime_ratio == points[i].runtime_ratio);
    CHECK(loaded[i].ccm.total_runtime == points[i].ccm.total_runtime);
    CHECK(loaded[i].runtime_ratio_thesis_estimate == points[i].runtime_ratio_thesis_estimate);
    CHECK(loaded[i].rigid.total_runtime_thesis_estimate ==
          points[i].rigid.total_runtime_thesis_estimate);
    // The designer's metrics, for the usable points (none for the unstable one).
    REQUIRE(loaded[i].impact_errors.has_value() == points[i].impact_errors.has_value());
    CHECK(points[i].impact_errors.has_value() == points[i].usable);
    if (!points[i].impact_errors) continue;
    CHECK(loaded[i].impact_errors->peak_force == points[i].impact_errors->peak_force);
    CHECK(loaded[i].impact_errors->indentation == points[i].impact_errors->indentation);
    CHECK(loaded[i].impact_errors->contact_duration == points[i].impact_errors->contact_duration);
    CHECK(loaded[i].impact_errors->rebound_speed == points[i].impact_errors->rebound_speed);
    CHECK(loaded[i].ccm_impact->peak_force == points[i].ccm_impact->peak_force);
    CHECK(loaded[i].rigid_impact->indentation == points[i].rigid_impact->indentation);
    CHECK(loaded[i].rigid_impact->contact_duration == points[i].rigid_impact->contact_duration);
    CHECK(loaded[i].ccm_impact->rebound_speed == points[i].ccm_impact->rebound_speed);
    CHECK(loaded[i].rigid_impact->approach_speed == points[i].rigid_impact->approach_speed);
  }

  const study::StudyFits fits = study::fit_study(points);
  store.save_fits(fits);
  store.save_fits(fits);  // replacing, not duplicating
  CHECK(test::count_rows(store.connection(), "SELECT count(*) FROM fits") ==
        static_cast<long long>(fits.fits.size()));
  const study::StudyFits back = store.load_fits();
  REQUIRE(back.fits.size() == fits.fits.size());
  for (const study::MetricFit& f : fits.fits) {
    const study::MetricFit* g = back.find(f.metric, f.kinetic_energy, f.axes);
    REQUIRE(g);
    CHECK(g->fit.surface.degree == f.fit.surface.degree);
    CHECK(g->fit.r_squared == f.fit.r_squared);
    CHECK(g->fit.loo_rmse == f.fit.loo_rmse);
    CHECK(g->fit.samples.size() == 11);
    CHECK(g->fit.surface(2.5, 0.7) == f.fit.surface(2.5, 0.7));
  }
  // The loaded fits recommend exactly what the fitted ones do (coefficients stored as REAL).
  study::RecommendQuery q;
  q.modulus_ratio = 300.0;
  q.length_ratio = 0.8;
  q.kinetic_energy = 50.0;
  const study::Recommendation from_memory = study::recommend(fits, points, q);
  const study::Recommendation from_store = study::recommend(back, loaded, q);
  CHECK(from_store.model == from_memory.model);
  CHECK(from_store.reason == from_memory.reason);
  CHECK(from_store.predicted.weighting.u_max == from_memory.predicted.weighting.u_max);
  REQUIRE(back.excluded.size() == 1);
  CHECK(back.excluded[0].point_index == 4);
  CHECK(back.excluded[0].reason.rfind("ccm run unstable", 0) == 0);
}

TEST_CASE("fits of several levels of another axis and the grid file round-trip", "[db]") {
  test::ScratchDir dir("db-fit-groups");
  db::StudyStore store(dir / "study.sqlite");
  store.open_study("damped", "g");
  CHECK_FALSE(store.load_grid());
  store.save_grid({"grids/damped.toml", "title = \"damped\"\n"});
  store.save_grid({"grids/damped.toml", "title = \"damped\"\n# edited\n"});  // replaces
  const auto grid = store.load_grid();
  REQUIRE(grid);
  CHECK(grid->source == "grids/damped.toml");
  CHECK(grid->text == "title = \"damped\"\n# edited\n");

  std::vector<study::PointMetrics> points;
  int index = 0;
  for (const double damping : {0.0, 1.0})
    for (const double er : {1.0, 1e2, 1e4})
      for (const double rls : {0.5, 1.0}) {
        study::RunRecord c = test::synthetic_run(ImpactModel::ccm, index);
        study::RunRecord r = test::synthetic_run(ImpactModel::rigid, index++);
        for (study::RunRecord* run : {&c, &r}) {
          run->point.modulus_ratio = er;
          run->point.length_ratio = rls;
          run->point.other_axes["damping"] = damping;
        }
        c.artifact.u_max.back() = 3.0 + damping + std::log10(er) * rls;
        store.add_grid_point(c.point);
        points.push_back(study::compute_point_metrics(c, r));
        store.save_metrics(points.back());
      }
  const study::StudyFits fits = study::fit_study(points);
  REQUIRE(fits.axis_groups().size() == 2);
  store.save_fits(fits);  // two fits per (metric, KE): the unique key holds the axes
  const study::StudyFits back = store.load_fits();
  REQUIRE(back.fits.size() == fits.fits.size());
  for (const study::MetricFit& f : fits.fits) {
    const study::MetricFit* g = back.find(f.metric, f.kinetic_energy, f.axes);
    REQUIRE(g);
    CHECK(g->fit.surface(1.5, 0.7) == f.fit.surface(1.5, 0.7));
  }
}
