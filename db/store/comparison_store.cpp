#include "db/store/comparison_store.hpp"

#include "db/schema/migrations.hpp"
#include "db/sqlite/statement.hpp"
#include "db/sqlite/transaction.hpp"
#include "db/store/provenance.hpp"

namespace ccm::db {

long long record_comparison(const std::filesystem::path& file, const ComparisonRow& r) {
  if (!std::filesystem::is_regular_file(file)) throw StoreError(file.string() + ": no such store");
  Connection c(file);
  migrate(c);
  c.exec("PRAGMA journal_mode = WAL", "cannot switch to WAL");
  const RunProvenance p = current_provenance("");
  Transaction transaction(c);
  Statement s(c,
              "INSERT INTO comparisons (scene, deformable_hash, rigid_hash, rigid_bodies, "
              "observables, max_error, worst_error, cost_ratio, answer, unusable, predicted, "
              "agrees, prediction_note, document, ccm_version, git_hash, host, recorded_at) "
              "VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14, ?15, ?16, "
              "?17, ?18)");
  s.bind(1, r.scene).bind(2, r.deformable_hash).bind(3, r.rigid_hash).bind(4, r.rigid_bodies);
  s.bind(5, r.observables).bind(6, r.max_error).bind(7, r.worst_error).bind(8, r.cost_ratio);
  r.answer.empty() ? s.bind_null(9) : s.bind(9, r.answer);
  s.bind(10, r.unusable);
  r.predicted.empty() ? s.bind_null(11) : s.bind(11, r.predicted);
  r.agrees ? s.bind(12, *r.agrees ? 1 : 0) : s.bind_null(12);
  s.bind(13, r.prediction_note).bind(14, r.document).bind(15, p.ccm_version);
  s.bind(16, p.git_hash).bind(17, p.host).bind(18, utc_now());
  s.run();
  const long long id = c.last_insert_rowid();
  transaction.commit();
  return id;
}

std::vector<ComparisonRow> load_comparisons(Connection& c) {
  std::vector<ComparisonRow> out;
  if (schema_version(c) < 6) return out;
  Statement q(c,
              "SELECT scene, deformable_hash, rigid_hash, rigid_bodies, observables, max_error, "
              "worst_error, cost_ratio, coalesce(answer, ''), unusable, coalesce(predicted, ''), "
              "agrees, prediction_note, document, recorded_at FROM comparisons ORDER BY id");
  while (q.step()) {
    ComparisonRow r;
    r.scene = q.column_text(0);
    r.deformable_hash = q.column_text(1);
    r.rigid_hash = q.column_text(2);
    r.rigid_bodies = q.column_text(3);
    r.observables = q.column_text(4);
    r.max_error = q.column_double(5);
    r.worst_error = q.column_optional_double(6);
    r.cost_ratio = q.column_optional_double(7);
    r.answer = q.column_text(8);
    r.unusable = q.column_text(9);
    r.predicted = q.column_text(10);
    if (!q.is_null(11)) r.agrees = q.column_int(11) != 0;
    r.prediction_note = q.column_text(12);
    r.document = q.column_text(13);
    r.recorded_at = q.column_text(14);
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace ccm::db
