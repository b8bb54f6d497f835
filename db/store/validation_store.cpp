#include "db/store/validation_store.hpp"

#include "db/schema/migrations.hpp"
#include "db/sqlite/statement.hpp"
#include "db/sqlite/transaction.hpp"
#include "db/store/provenance.hpp"

namespace ccm::db {
namespace {

void insert_score(Connection& c, long long id, const ValidationScoreRow& r) {
  Statement s(c,
              "INSERT INTO validation_scores (validation_id, channel, against, left_out, samples, "
              "nrmse, peak_measured, peak_simulated, peak_time_error, corridor, phase, "
              "magnitude, slope, rating, grade) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, "
              "?10, ?11, ?12, ?13, ?14, ?15)");
  s.bind(1, id).bind(2, r.channel).bind(3, r.against).bind(4, r.left_out ? 1 : 0);
  s.bind(5, r.samples).bind(6, r.nrmse).bind(7, r.peak_measured).bind(8, r.peak_simulated);
  s.bind(9, r.peak_time_error).bind(10, r.corridor).bind(11, r.phase).bind(12, r.magnitude);
  s.bind(13, r.slope).bind(14, r.rating).bind(15, r.grade);
  s.run();
}

void insert_curves(Connection& c, long long id, const ValidationCurvesRow& r) {
  Statement s(c,
              "INSERT INTO validation_curves (validation_id, channel, unit, curves_csv) VALUES "
              "(?1, ?2, ?3, ?4)");
  s.bind(1, id).bind(2, r.channel).bind(3, r.unit).bind(4, r.curves_csv);
  s.run();
}

std::vector<ValidationScoreRow> load_scores(Connection& c, long long id) {
  std::vector<ValidationScoreRow> out;
  Statement q(c,
              "SELECT channel, against, left_out, samples, nrmse, peak_measured, peak_simulated, "
              "peak_time_error, corridor, phase, magnitude, slope, rating, grade FROM "
              "validation_scores WHERE validation_id = ?1 ORDER BY rowid");
  q.bind(1, id);
  while (q.step()) {
    ValidationScoreRow r;
    r.channel = q.column_text(0);
    r.against = q.column_text(1);
    r.left_out = q.column_int(2) != 0;
    r.samples = q.column_int(3);
    r.nrmse = q.column_optional_double(4);
    r.peak_measured = q.column_double(5);
    r.peak_simulated = q.column_double(6);
    r.peak_time_error = q.column_double(7);
    r.corridor = q.column_double(8);
    r.phase = q.column_double(9);
    r.magnitude = q.column_double(10);
    r.slope = q.column_double(11);
    r.rating = q.column_double(12);
    r.grade = q.column_text(13);
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<ValidationCurvesRow> load_curves(Connection& c, long long id) {
  std::vector<ValidationCurvesRow> out;
  Statement q(c,
              "SELECT channel, unit, curves_csv FROM validation_curves WHERE validation_id = ?1 "
              "ORDER BY rowid");
  q.bind(1, id);
  while (q.step()) out.push_back({q.column_text(0), q.column_text(1), q.column_text(2)});
  return out;
}

}  // namespace

long long record_validation(const std::filesystem::path& file, const ValidationRow& r) {
  if (!std::filesystem::is_regular_file(file)) throw StoreError(file.string() + ": no such store");
  Connection c(file);
  migrate(c);
  c.exec("PRAGMA journal_mode = WAL", "cannot switch to WAL");
  const RunProvenance p = current_provenance("");
  Transaction transaction(c);
  Statement s(c,
              "INSERT INTO validations (scene, data, fitted, document, ccm_version, git_hash, "
              "host, recorded_at) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8)");
  s.bind(1, r.scene).bind(2, r.data).bind(3, r.fitted).bind(4, r.document);
  s.bind(5, p.ccm_version).bind(6, p.git_hash).bind(7, p.host).bind(8, utc_now());
  s.run();
  const long long id = c.last_insert_rowid();
  for (const ValidationScoreRow& score : r.scores) insert_score(c, id, score);
  for (const ValidationCurvesRow& curves : r.curves) insert_curves(c, id, curves);
  transaction.commit();
  return id;
}

std::vector<ValidationRow> load_validations(Connection& c) {
  std::vector<ValidationRow> out;
  if (schema_version(c) < 9) return out;
  std::vector<long long> ids;
  {
    Statement q(c,
                "SELECT id, scene, data, fitted, document, recorded_at FROM validations ORDER BY "
                "id");
    while (q.step()) {
      ValidationRow r;
      ids.push_back(q.column_int(0));
      r.scene = q.column_text(1);
      r.data = q.column_text(2);
      r.fitted = q.column_text(3);
      r.document = q.column_text(4);
      r.recorded_at = q.column_text(5);
      out.push_back(std::move(r));
    }
  }
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i].scores = load_scores(c, ids[i]);
    out[i].curves = load_curves(c, ids[i]);
  }
  return out;
}

}  // namespace ccm::db
