// The trade study's system of record: one SQLite file per study (WAL, versioned schema, see
// docs/store.md) and one HDF5 file of artifact histories per run in "<stem>.histories/" beside
// it (found again after the store and its folder are renamed or moved). Every write is one short
// transaction; two processes may write the same file at once (each waits on the other's lock up to
// the busy timeout).
//
// Typical use by a study runner:
//   StudyStore store("study.sqlite");
//   store.open_study("table-2.2", grid_hash);
//   for each point p, model m:
//     if (store.is_done(p, m)) continue;                // resume: completed or unstable
//     store.mark_running(p, m, provenance, utc_now());  // visible to `status`
//     store.record_run(runner(p, m), provenance);       // HDF5 first, then one transaction
//   store.save_metrics(compute_point_metrics(ccm_run, rigid_run));
//   store.save_fits(fit_study(store.load_metrics()));
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "db/sqlite/connection.hpp"
#include "db/sqlite/transaction.hpp"
#include "db/store/provenance.hpp"
#include "records/grid_point.hpp"
#include "records/point_metrics.hpp"
#include "records/run_record.hpp"
#include "study/fit/study_fits.hpp"

namespace ccm::db {

// Status of one run row.
enum class RunStatus { running, completed, unstable, failed };
std::string_view to_string(RunStatus status);

// Status of a grid point from its two runs: running if either runs; else failed, unstable if
// either is; done when both completed; pending otherwise (a run missing).
enum class PointState { pending, running, done, unstable, failed };
std::string_view to_string(PointState state);

// The grid file a study was run from, as `ccm study run` read it (schema step 5).
struct StoredGrid {
  std::string source;  // the path as given
  std::string text;    // the file's text
};

struct PointStatus {
  study::GridPoint point;
  std::string content_hash;
  PointState state = PointState::pending;
  std::optional<RunStatus> ccm, rigid;
  std::string reason;  // the first non-empty run reason (instability or failure)
};

class StudyStore {
 public:
  // read_write: opens or creates the store, migrating an older schema. read_only (the reading
  // commands): opens an existing store and writes nothing, not even beside it; a store of an
  // older schema is migrated in an in-memory copy. Throws StoreError naming the file when it is
  // not a ccm study store (read_only: an empty file too) or was written by a newer ccm.
  explicit StudyStore(const std::filesystem::path& file, Access access = Access::read_write);

  // Binds the store to its study, creating it on first use. Throws StoreError when the file
  // already holds a study of another name or grid hash (the grid file changed).
  void open_study(const std::string& name, const std::string& grid_hash);
  std::string study_name() const;
  // Binds the store to the study the file already holds, for reading commands (status,
  // recommend, report); false when it holds none. Never creates one.
  bool open_existing_study();

  // Adds the point (idempotent by content hash); returns its row id.
  long long add_grid_point(const study::GridPoint& point);

  // Resume queries, by point content hash (db/store/point_key.hpp) and model.
  std::optional<RunStatus> run_status(const std::string& point_hash, study::ImpactModel m) const;
  // True when a final result exists: completed or unstable (both deterministic; a running or
  // failed row is redone).
  bool is_done(const std::string& point_hash, study::ImpactModel model) const;
  bool is_done(const study::GridPoint& point, study::ImpactModel model) const;

  // Records that the run has started (status "running"), unless it is already done; returns
  // false in that case. An interrupted run stays "running" and is redone on resume, replacing
  // its row (one row per point and model).
  bool mark_running(const study::GridPoint& point, study::ImpactModel model,
                    const RunProvenance& provenance, const std::string& started_at);
  // Writes the histories to HDF5, then the run row with its figures, verdict and provenance in
  // one transaction (status "completed" or "unstable").
  void record_run(const study::RunRecord& run, const RunProvenance& provenance);
  // Records an internal failure (status "failed") with its message.
  void record_failure(const study::GridPoint& point, study::ImpactModel model,
                      const std::string& message, const RunProvenance& provenance);
  // The stored run with its histories read back from HDF5; empty when no completed or
  // unstable run exists.
  std::optional<study::RunRecord> load_run(const study::GridPoint& point,
                                           study::ImpactModel model) const;

  // One entry per grid point, in point index order.
  std::vector<PointStatus> status() const;

  // Metrics per point (replacing earlier ones) and all fits (replacing the study's fits).
  void save_metrics(const study::PointMetrics& metrics);  // with the designer's metrics
  std::vector<study::PointMetrics> load_metrics() const;
  void save_fits(const study::StudyFits& fits);
  study::StudyFits load_fits() const;

  // The study's grid file (replacing an earlier one); empty when the store predates schema
  // step 5 or no `ccm study run` has saved it since.
  void save_grid(const StoredGrid& grid);
  std::optional<StoredGrid> load_grid() const;

  // Groups several writes into one atomic transaction (the store's own writes nest in it).
  Transaction begin() { return Transaction(*connection_); }

  const std::filesystem::path& file() const { return file_; }
  // "<stem>.histories" beside the store file, where new histories are written.
  std::filesystem::path history_dir() const;
  // Where a run's stored history_file is: in history_dir() under its own name (a store renamed
  // or moved together with its histories folder), else at the stored path relative to the store
  // file (a store renamed without it). Throws StoreError naming both when neither exists.
  std::filesystem::path history_path(const std::string& stored) const;
  Connection& connection() const { return *connection_; }

 private:
  void save_impact_metrics(const study::PointMetrics& metrics);
  long long study_id() const;
  long long point_id(const study::GridPoint& point);
  long long point_id_by_index(int point_index) const;
  std::optional<long long> find_point_id(const std::string& point_hash) const;
  long long reused_run_id(int point_index, study::ImpactModel model) const;
  void upsert_run(long long point_id, const study::RunRecord& run, const RunProvenance& prov,
                  RunStatus status, const std::string& history_file);

  std::filesystem::path file_;
  std::unique_ptr<Connection> connection_;
  std::optional<long long> study_id_;
};

}  // namespace ccm::db
