// StudyStore: the runs table (one row per point and model) and the run histories in HDF5.
#include <fmt/format.h>

#include <array>

#include "db/history/history_file.hpp"
#include "db/sqlite/statement.hpp"
#include "db/store/point_key.hpp"
#include "db/store/row_codes.hpp"
#include "db/store/study_store.hpp"

namespace ccm::db {

namespace {

// Column order of the upsert; the binds in upsert_run follow it.
constexpr std::array<const char*, 36> kRunColumns = {"grid_point_id",
                                                     "model",
                                                     "status",
                                                     "reason",
                                                     "unstable_time",
                                                     "steps",
                                                     "wall_seconds",
                                                     "initial_stable_dt",
                                                     "average_iteration_seconds",
                                                     "dt_min",
                                                     "dt_max",
                                                     "max_energy_error",
                                                     "n_elements",
                                                     "n_nodes",
                                                     "history_file",
                                                     "history_dataset",
                                                     "scene_hash",
                                                     "grid_hash",
                                                     "ccm_version",
                                                     "git_hash",
                                                     "host",
                                                     "pid",
                                                     "ranks",
                                                     "jobs",
                                                     "started_at",
                                                     "ended_at",
                                                     "step_cpu_seconds",
                                                     "step_wall_seconds",
                                                     "dt_first",
                                                     "dt_mean",
                                                     "steps_structure",
                                                     "steps_contact",
                                                     "steps_max_dt",
                                                     "steps_landing",
                                                     "dt_contact_min",
                                                     "reuses_run_id"};

// INSERT ... ON CONFLICT (grid_point_id, model) DO UPDATE: one row per point and model, so a
// redone run replaces its row instead of duplicating it. `guard` limits which rows may be
// replaced.
std::string upsert_sql(std::string_view guard) {
  std::string columns, values, updates;
  for (std::size_t i = 0; i < kRunColumns.size(); ++i) {
    columns += fmt::format("{}{}", i ? ", " : "", kRunColumns[i]);
    values += fmt::format("{}?{}", i ? ", " : "", i + 1);
    if (i >= 2)
      updates +=
          fmt::format("{}{} = excluded.{}", i > 2 ? ", " : "", kRunColumns[i], kRunColumns[i]);
  }
  return fmt::format(
      "INSERT INTO runs ({}) VALUES ({}) ON CONFLICT (grid_point_id, model) DO UPDATE SET {}{}",
      columns, values, updates, guard);
}

constexpr std::string_view kNotDone = " WHERE runs.status NOT IN ('completed', 'unstable')";

RunStatus status_of(const study::RunRecord& run) {
  if (run.verdict == "completed") return RunStatus::completed;
  if (run.verdict == "unstable") return RunStatus::unstable;
  throw StoreError("run of grid point " + std::to_string(run.point.index) + " has verdict \"" +
                   run.verdict + "\", expected \"completed\" or \"unstable\"");
}

void bind_provenance(Statement& s, const RunProvenance& p) {
  s.bind(18, p.grid_hash).bind(19, p.ccm_version).bind(20, p.git_hash).bind(21, p.host);
  s.bind(22, static_cast<long long>(p.pid)).bind(23, p.ranks).bind(24, p.jobs);
}

// Columns 27-35: the measured cost (NULL when the record has none).
void bind_cost(Statement& s, const study::MeasuredCost& c) {
  s.bind(27, c.step_cpu_seconds).bind(28, c.step_wall_seconds).bind(29, c.dt_first);
  s.bind(30, c.dt_mean).bind(31, c.steps_structure).bind(32, c.steps_contact);
  s.bind(33, c.steps_max_dt).bind(34, c.steps_landing).bind(35, c.dt_contact_min);
}

std::optional<study::MeasuredCost> cost_from_row(const Statement& q, int first) {
  if (q.is_null(first)) return std::nullopt;  // stored before schema 4: not measured
  study::MeasuredCost c;
  c.step_cpu_seconds = q.column_double(first);
  c.step_wall_seconds = q.column_double(first + 1);
  c.dt_first = q.column_double(first + 2);
  c.dt_mean = q.column_double(first + 3);
  c.steps_structure = static_cast<long>(q.column_int(first + 4));
  c.steps_contact = static_cast<long>(q.column_int(first + 5));
  c.steps_max_dt = static_cast<long>(q.column_int(first + 6));
  c.steps_landing = static_cast<long>(q.column_int(first + 7));
  c.dt_contact_min = q.column_optional_double(first + 8);
  return c;
}

}  // namespace

void StudyStore::upsert_run(long long point_id, const study::RunRecord& run,
                            const RunProvenance& prov, RunStatus status,
                            const std::string& history_file) {
  const bool finished = status == RunStatus::completed || status == RunStatus::unstable;
  Statement s(*connection_, upsert_sql(status == RunStatus::running ? kNotDone : ""));
  s.bind(1, point_id).bind(2, study::to_string(run.model)).bind(3, to_string(status));
  s.bind(4, run.reason);
  if (finished) {
    s.bind(5, run.completed() ? std::nullopt : std::optional(run.unstable_time));
    s.bind(6, run.steps).bind(7, run.wall_seconds).bind(8, run.initial_stable_dt);
    s.bind(9, run.average_iteration_seconds).bind(10, run.dt_min).bind(11, run.dt_max);
    s.bind(12, run.max_energy_error).bind(13, run.n_elements).bind(14, run.n_nodes);
    s.bind(15, history_file).bind(16, kArtifactGroup);
    if (run.cost) bind_cost(s, *run.cost);
    if (run.reuses_point) s.bind(36, reused_run_id(*run.reuses_point, run.model));
  }
  s.bind(17, run.scene_hash);
  bind_provenance(s, prov);
  s.bind(25, run.started_at.empty() ? utc_now() : run.started_at);
  if (status != RunStatus::running) s.bind(26, run.ended_at.empty() ? utc_now() : run.ended_at);
  s.run();
}

long long StudyStore::reused_run_id(int point_index, study::ImpactModel model) const {
  Statement q(*connection_, "SELECT id FROM runs WHERE grid_point_id = ?1 AND model = ?2");
  q.bind(1, point_id_by_index(point_index)).bind(2, study::to_string(model));
  if (!q.step())
    throw StoreError(
        fmt::format("{}: the {} run of grid point {} that another run reuses is not stored",
                    file_.string(), study::to_string(model), point_index));
  return q.column_int(0);
}

std::optional<RunStatus> StudyStore::run_status(const std::string& point_hash,
                                                study::ImpactModel model) const {
  Statement query(*connection_, R"sql(
    SELECT r.status FROM runs r JOIN grid_points gp ON gp.id = r.grid_point_id
    WHERE gp.study_id = ?1 AND gp.content_hash = ?2 AND r.model = ?3)sql");
  query.bind(1, study_id()).bind(2, point_hash).bind(3, study::to_string(model));
  if (!query.step()) return std::nullopt;
  return run_status_from_text(query.column_text(0));
}

bool StudyStore::is_done(const std::string& point_hash, study::ImpactModel model) const {
  const auto s = run_status(point_hash, model);
  return s == RunStatus::completed || s == RunStatus::unstable;
}

bool StudyStore::is_done(const study::GridPoint& point, study::ImpactModel model) const {
  return is_done(grid_point_hash(point), model);
}

bool StudyStore::mark_running(const study::GridPoint& point, study::ImpactModel model,
                              const RunProvenance& provenance, const std::string& started_at) {
  Transaction transaction(*connection_);
  study::RunRecord run;
  run.point = point;
  run.model = model;
  run.started_at = started_at;
  upsert_run(point_id(point), run, provenance, RunStatus::running, "");
  const bool claimed = connection_->changes() > 0;
  transaction.commit();
  return claimed;
}

void StudyStore::record_run(const study::RunRecord& run, const RunProvenance& provenance) {
  const RunStatus status = status_of(run);
  const std::string name =
      fmt::format("{}-{}.h5", grid_point_hash(run.point), study::to_string(run.model));
  std::filesystem::create_directories(history_dir());
  write_history_file(history_dir() / name, run.artifact,
                     run.impactor);  // complete before it is referenced
  Transaction transaction(*connection_);
  upsert_run(point_id(run.point), run, provenance, status,
             (std::filesystem::path(history_dir().filename()) / name).string());
  transaction.commit();
}

void StudyStore::record_failure(const study::GridPoint& point, study::ImpactModel model,
                                const std::string& message, const RunProvenance& provenance) {
  Transaction transaction(*connection_);
  study::RunRecord run;
  run.point = point;
  run.model = model;
  run.reason = message;
  upsert_run(point_id(point), run, provenance, RunStatus::failed, "");
  transaction.commit();
}

std::optional<study::RunRecord> StudyStore::load_run(const study::GridPoint& point,
                                                     study::ImpactModel model) const {
  Statement q(*connection_, R"sql(
    SELECT gp.point_index, gp.content_hash, gp.modulus_ratio, gp.length_ratio,
           gp.kinetic_energy, gp.other_axes, r.status, r.reason, r.unstable_time, r.steps,
           r.wall_seconds, r.initial_stable_dt, r.average_iteration_seconds, r.dt_min, r.dt_max,
           r.max_energy_error, r.n_elements, r.n_nodes, r.scene_hash, r.started_at, r.ended_at,
           r.history_file, r.history_dataset, r.step_cpu_seconds, r.step_wall_seconds,
           r.dt_first, r.dt_mean, r.steps_structure, r.steps_contact, r.steps_max_dt,
           r.steps_landing, r.dt_contact_min, reused.point_index
    FROM runs r JOIN grid_points gp ON gp.id = r.grid_point_id
    LEFT JOIN runs rr ON rr.id = r.reuses_run_id
    LEFT JOIN grid_points reused ON reused.id = rr.grid_point_id
    WHERE gp.study_id = ?1 AND gp.content_hash = ?2 AND r.model = ?3
      AND r.status IN ('completed', 'unstable'))sql");
  q.bind(1, study_id()).bind(2, grid_point_hash(point)).bind(3, study::to_string(model));
  if (!q.step()) return std::nullopt;
  study::RunRecord run;
  run.point = point_from_row(q, 0);
  run.model = model;
  run.verdict = q.column_text(6);
  run.reason = q.column_text(7);
  run.unstable_time = q.column_optional_double(8).value_or(0.0);
  run.steps = static_cast<long>(q.column_int(9));
  run.wall_seconds = q.column_double(10);
  run.initial_stable_dt = q.column_double(11);
  run.average_iteration_seconds = q.column_double(12);
  run.dt_min = q.column_double(13);
  run.dt_max = q.column_double(14);
  run.max_energy_error = q.column_double(15);
  run.n_elements = static_cast<long>(q.column_int(16));
  run.n_nodes = static_cast<long>(q.column_int(17));
  run.scene_hash = q.column_text(18);
  run.started_at = q.column_text(19);
  run.ended_at = q.column_text(20);
  run.cost = cost_from_row(q, 23);
  if (!q.is_null(32)) run.reuses_point = static_cast<int>(q.column_int(32));
  const std::string dataset = q.column_text(22);
  run.artifact = read_history_file(history_path(q.column_text(21)), dataset.c_str());
  run.impactor = read_impactor_history(history_path(q.column_text(21)));
  return run;
}

}  // namespace ccm::db
