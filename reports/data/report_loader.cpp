#include "reports/data/report_loader.hpp"

#include <set>
#include <string>

#include "db/sqlite/statement.hpp"
#include "reports/data/rig_loader.hpp"
#include "study/grid/grid_file.hpp"

namespace ccm::reports {
namespace {

std::vector<std::string> distinct_texts(db::Connection& connection, const char* sql) {
  std::vector<std::string> out;
  db::Statement query(connection, sql);
  while (query.step()) out.push_back(query.column_text(0));
  return out;
}

StudyProvenance load_provenance(const db::StudyStore& store) {
  db::Connection& c = store.connection();
  StudyProvenance p;
  db::Statement study(c, "SELECT name, grid_hash, created_at FROM studies ORDER BY id LIMIT 1");
  if (study.step()) {
    p.study_name = study.column_text(0);
    p.grid_hash = study.column_text(1);
    p.created_at = study.column_text(2);
  }
  p.ccm_versions = distinct_texts(
      c, "SELECT DISTINCT ccm_version || ' (git ' || git_hash || ')' FROM runs ORDER BY 1");
  p.hosts = distinct_texts(c, "SELECT DISTINCT host FROM runs ORDER BY 1");
  p.scene_hashes =
      distinct_texts(c, "SELECT DISTINCT scene_hash FROM runs WHERE scene_hash <> '' ORDER BY 1");
  db::Statement span(c, "SELECT min(started_at), max(ended_at) FROM runs");
  if (span.step()) {
    p.first_run_started_at = span.is_null(0) ? "" : span.column_text(0);
    p.last_run_ended_at = span.is_null(1) ? "" : span.column_text(1);
  }
  return p;
}

}  // namespace

ReportData load_report_data(const db::StudyStore& store) {
  ReportData data;
  data.database = store.file().string();
  data.provenance = load_provenance(store);
  data.status = store.status();
  for (const db::PointStatus& s : data.status)
    for (study::ImpactModel m : {study::ImpactModel::ccm, study::ImpactModel::rigid})
      if (auto run = store.load_run(s.point, m)) data.runs.push_back(std::move(*run));
  for (study::PointMetrics& m : store.load_metrics())
    (is_convergence_point(m.point) ? data.convergence : data.grid).push_back(std::move(m));
  data.fits = study::fit_study(data.grid);
  if (const auto grid = store.load_grid())
    data.grid_spec = study::parse_grid(grid->text, grid->source);
  data.rig = load_rig_report_data(store.connection());
  data.comparisons = db::load_comparisons(store.connection());
  data.validations = db::load_validations(store.connection());
  return data;
}

}  // namespace ccm::reports
