// StudyStore: opening, the study row, grid points and the status query.
// Run rows are in run_rows.cpp, metrics and fits in result_rows.cpp.
#include "db/store/study_store.hpp"

#include "db/schema/migrations.hpp"
#include "db/sqlite/statement.hpp"
#include "db/store/point_key.hpp"
#include "db/store/row_codes.hpp"
#include "records/provenance/version.hpp"

namespace ccm::db {

std::string_view to_string(RunStatus status) {
  switch (status) {
    case RunStatus::running:
      return "running";
    case RunStatus::completed:
      return "completed";
    case RunStatus::unstable:
      return "unstable";
    case RunStatus::failed:
      return "failed";
  }
  return "unknown";
}

std::string_view to_string(PointState state) {
  switch (state) {
    case PointState::pending:
      return "pending";
    case PointState::running:
      return "running";
    case PointState::done:
      return "done";
    case PointState::unstable:
      return "unstable";
    case PointState::failed:
      return "failed";
  }
  return "unknown";
}

StudyStore::StudyStore(const std::filesystem::path& file, Access access)
    : file_(file), connection_(std::make_unique<Connection>(file, access)) {
  if (access == Access::read_only) {
    if (check_existing_store(*connection_) < latest_schema_version()) {
      connection_->copy_into_memory();
      migrate(*connection_);
    }
  } else {
    migrate(*connection_);
    connection_->exec("PRAGMA journal_mode = WAL", "cannot switch to WAL");
  }
  connection_->exec("PRAGMA foreign_keys = ON", "cannot enable foreign keys");
  Statement study(*connection_, "SELECT id FROM studies ORDER BY id LIMIT 1");
  if (study.step()) study_id_ = study.column_int(0);
}

void StudyStore::open_study(const std::string& name, const std::string& grid_hash) {
  Transaction transaction(*connection_);
  Statement existing(*connection_, "SELECT id, name, grid_hash FROM studies ORDER BY id LIMIT 1");
  if (existing.step()) {
    if (existing.column_text(1) != name || existing.column_text(2) != grid_hash)
      throw StoreError(file_.string() + ": holds study \"" + existing.column_text(1) +
                       "\" (grid hash " + existing.column_text(2) + "), not \"" + name +
                       "\" (grid hash " + grid_hash +
                       "); one file per study: choose another file or restore the grid file");
    study_id_ = existing.column_int(0);
    return;
  }
  Statement insert(*connection_,
                   "INSERT INTO studies (name, grid_hash, created_at, ccm_version, git_hash) "
                   "VALUES (?1, ?2, ?3, ?4, ?5)");
  insert.bind(1, name)
      .bind(2, grid_hash)
      .bind(3, utc_now())
      .bind(4, ccm_version())
      .bind(5, git_hash());
  insert.run();
  study_id_ = connection_->last_insert_rowid();
  transaction.commit();
}

bool StudyStore::open_existing_study() {
  Statement existing(*connection_, "SELECT id FROM studies ORDER BY id LIMIT 1");
  if (!existing.step()) return false;
  study_id_ = existing.column_int(0);
  return true;
}

std::string StudyStore::study_name() const {
  Statement query(*connection_, "SELECT name FROM studies WHERE id = ?1");
  query.bind(1, study_id());
  return query.step() ? query.column_text(0) : std::string();
}

long long StudyStore::study_id() const {
  if (!study_id_) throw StoreError(file_.string() + ": no study opened in this store yet");
  return *study_id_;
}

std::filesystem::path StudyStore::history_dir() const {
  return file_.parent_path() / (file_.stem().string() + ".histories");
}

std::filesystem::path StudyStore::history_path(const std::string& stored) const {
  const std::filesystem::path stored_path(stored);
  const std::filesystem::path in_own_folder = history_dir() / stored_path.filename();
  const std::filesystem::path as_stored = file_.parent_path() / stored_path;
  std::error_code ignored;
  if (std::filesystem::exists(in_own_folder, ignored)) return in_own_folder;
  if (std::filesystem::exists(as_stored, ignored)) return as_stored;
  throw StoreError(file_.string() + ": the history file " + stored_path.filename().string() +
                   " is in neither " + in_own_folder.parent_path().string() + " nor " +
                   as_stored.parent_path().string() +
                   " (a store is moved or renamed together with its <name>.histories folder)");
}

long long StudyStore::add_grid_point(const study::GridPoint& point) {
  Transaction transaction(*connection_);
  const long long id = point_id(point);
  transaction.commit();
  return id;
}

// Inserts the point if absent (caller holds a transaction); returns its id.
long long StudyStore::point_id(const study::GridPoint& point) {
  const std::string hash = grid_point_hash(point);
  if (const auto id = find_point_id(hash)) return *id;
  Statement insert(*connection_,
                   "INSERT INTO grid_points (study_id, point_index, content_hash, modulus_ratio, "
                   "length_ratio, kinetic_energy, other_axes) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7)");
  insert.bind(1, study_id()).bind(2, point.index).bind(3, hash).bind(4, point.modulus_ratio);
  insert.bind(5, point.length_ratio).bind(6, point.kinetic_energy).bind(7, other_axes_text(point));
  insert.run();
  return connection_->last_insert_rowid();
}

std::optional<long long> StudyStore::find_point_id(const std::string& point_hash) const {
  Statement query(*connection_,
                  "SELECT id FROM grid_points WHERE study_id = ?1 AND content_hash = ?2");
  query.bind(1, study_id()).bind(2, point_hash);
  if (!query.step()) return std::nullopt;
  return query.column_int(0);
}

long long StudyStore::point_id_by_index(int point_index) const {
  Statement query(*connection_,
                  "SELECT id FROM grid_points WHERE study_id = ?1 AND point_index = ?2");
  query.bind(1, study_id()).bind(2, point_index);
  if (!query.step())
    throw StoreError(file_.string() + ": no grid point with index " + std::to_string(point_index));
  return query.column_int(0);
}

namespace {

PointState point_state(const std::optional<RunStatus>& a, const std::optional<RunStatus>& b) {
  auto either = [&](RunStatus s) { return a == s || b == s; };
  if (either(RunStatus::running)) return PointState::running;
  if (either(RunStatus::failed)) return PointState::failed;
  if (either(RunStatus::unstable)) return PointState::unstable;
  if (a == RunStatus::completed && b == RunStatus::completed) return PointState::done;
  return PointState::pending;
}

}  // namespace

std::vector<PointStatus> StudyStore::status() const {
  Statement query(*connection_, R"sql(
    SELECT gp.point_index, gp.content_hash, gp.modulus_ratio, gp.length_ratio,
           gp.kinetic_energy, gp.other_axes, c.status, r.status,
           COALESCE(NULLIF(c.reason, ''), r.reason, '')
    FROM grid_points gp
    LEFT JOIN runs c ON c.grid_point_id = gp.id AND c.model = 'ccm'
    LEFT JOIN runs r ON r.grid_point_id = gp.id AND r.model = 'rigid'
    WHERE gp.study_id = ?1 ORDER BY gp.point_index)sql");
  query.bind(1, study_id());
  std::vector<PointStatus> out;
  while (query.step()) {
    PointStatus s;
    s.point = point_from_row(query, 0);
    s.content_hash = query.column_text(1);
    if (!query.is_null(6)) s.ccm = run_status_from_text(query.column_text(6));
    if (!query.is_null(7)) s.rigid = run_status_from_text(query.column_text(7));
    s.state = point_state(s.ccm, s.rigid);
    s.reason = query.column_text(8);
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace ccm::db
