// Everything a report shows, as plain structs read once from the study store
// (reports/data/report_loader.hpp): rendering never touches the database.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "db/store/comparison_store.hpp"
#include "db/store/validation_store.hpp"
#include "db/store/rig_reader.hpp"
#include "db/store/study_store.hpp"
#include "records/point_metrics.hpp"
#include "records/run_record.hpp"
#include "study/fit/study_fits.hpp"
#include "study/grid/grid_spec.hpp"

namespace ccm::reports {

// Where the study's results came from (the runs rows) and where the report was made.
struct StudyProvenance {
  std::string study_name{};
  std::string grid_hash{};
  std::string created_at;                 // when the study was created (UTC)
  std::vector<std::string> ccm_versions;  // distinct "version (git hash)" of the runs
  std::vector<std::string> hosts{};       // distinct hosts that ran them
  std::string first_run_started_at{}, last_run_ended_at{};
  std::vector<std::string> scene_hashes{};  // distinct scene content hashes of the runs
};

// The benchtop rig's records of the same store (reports/data/rig_loader.hpp).
struct RigReportData {
  std::vector<db::StoredRigRun> runs{};  // latest purpose='run' row per case and drive
  std::vector<db::RigCalibrationRecord> calibrations{};
  bool empty() const { return runs.empty() && calibrations.empty(); }
};

struct ReportData {
  std::string database{};  // path of the store, as given
  StudyProvenance provenance{};
  std::vector<db::PointStatus> status{};         // every grid point, in index order
  std::vector<study::RunRecord> runs{};          // every completed or unstable run, with histories
  std::vector<study::PointMetrics> grid{};       // metrics of the main grid's points
  std::vector<study::PointMetrics> convergence;  // metrics of convergence points (mesh_scale)
  // Fitted to `grid` when loaded (study::fit_study), so that they always match the measured
  // points and this ccm's fitting rules.
  study::StudyFits fits{};
  // The grid file the study was run from (schema step 5); empty for an older store.
  std::optional<study::GridSpec> grid_spec{};
  RigReportData rig{};
  std::vector<db::ComparisonRow> comparisons{};  // `ccm compare` records (schema step 6)
  std::vector<db::ValidationRow> validations{};  // `ccm validate` records (schema step 9)
};

// True for the points of the convergence mode (they carry other_axes["mesh_scale"]).
using study::is_convergence_point;

}  // namespace ccm::reports
