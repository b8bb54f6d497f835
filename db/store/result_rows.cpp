// StudyStore: the metrics table (one row per point) and the fits with their terms and points.
#include <cmath>

#include "db/sqlite/statement.hpp"
#include "db/store/point_key.hpp"
#include "db/store/row_codes.hpp"
#include "db/store/study_store.hpp"

namespace ccm::db {

namespace {

std::optional<double> if_usable(const study::PointMetrics& m, double value) {
  return m.usable ? std::optional(value) : std::nullopt;
}

}  // namespace

void StudyStore::save_metrics(const study::PointMetrics& m) {
  Transaction transaction(*connection_);
  Statement s(*connection_, R"sql(
    INSERT OR REPLACE INTO metrics (grid_point_id, usable, excluded_reason,
      cumulative_u_mean, cumulative_u_max, cumulative_kinetic_energy,
      final_u_mean, final_u_max, final_kinetic_energy, nt_ccm, nt_rigid, tr_ccm, tr_rigid, rtr,
      w_u_mean, w_u_max, w_kinetic_energy, t_final, computed_at, tr_ccm_thesis_estimate,
      tr_rigid_thesis_estimate, rtr_thesis_estimate)
    VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14, ?15, ?16, ?17, ?18, ?19,
            ?20, ?21, ?22))sql");
  s.bind(1, point_id(m.point)).bind(2, m.usable ? 1 : 0).bind(3, m.excluded_reason);
  s.bind(4, if_usable(m, m.cumulative.u_mean)).bind(5, if_usable(m, m.cumulative.u_max));
  s.bind(6, if_usable(m, m.cumulative.kinetic_energy));
  s.bind(7, if_usable(m, m.final_state.u_mean)).bind(8, if_usable(m, m.final_state.u_max));
  s.bind(9, if_usable(m, m.final_state.kinetic_energy));
  s.bind(10, if_usable(m, m.ccm.normalised_runtime));
  s.bind(11, if_usable(m, m.rigid.normalised_runtime));
  s.bind(12, if_usable(m, m.ccm.total_runtime)).bind(13, if_usable(m, m.rigid.total_runtime));
  s.bind(14, if_usable(m, m.runtime_ratio));
  s.bind(15, if_usable(m, m.weighting.u_mean)).bind(16, if_usable(m, m.weighting.u_max));
  s.bind(17, if_usable(m, m.weighting.kinetic_energy)).bind(18, if_usable(m, m.t_final));
  s.bind(19, utc_now());
  s.bind(20, if_usable(m, m.ccm.total_runtime_thesis_estimate));
  s.bind(21, if_usable(m, m.rigid.total_runtime_thesis_estimate));
  s.bind(22, if_usable(m, m.runtime_ratio_thesis_estimate));
  s.run();
  save_impact_metrics(m);
  transaction.commit();
}

// The designer's metrics of a point, NULL where it has none.
void StudyStore::save_impact_metrics(const study::PointMetrics& m) {
  Statement s(*connection_, R"sql(
    UPDATE metrics SET peak_force_ccm = ?2, peak_force_rigid = ?3, indentation_ccm = ?4,
      indentation_rigid = ?5, contact_duration_ccm = ?6, contact_duration_rigid = ?7,
      rebound_speed_ccm = ?8, rebound_speed_rigid = ?9, approach_speed = ?10,
      error_peak_force = ?11, error_indentation = ?12, error_contact_duration = ?13,
      error_rebound_speed = ?14
    WHERE grid_point_id = ?1)sql");
  s.bind(1, point_id(m.point));
  const bool has = m.ccm_impact && m.rigid_impact && m.impact_errors;
  const auto put = [&](int column, double value) {
    if (has)
      s.bind(column, value);
    else
      s.bind_null(column);
  };
  const study::ImpactQuantities c = m.ccm_impact.value_or(study::ImpactQuantities{});
  const study::ImpactQuantities r = m.rigid_impact.value_or(study::ImpactQuantities{});
  const study::ImpactErrors e = m.impact_errors.value_or(study::ImpactErrors{});
  put(2, c.peak_force), put(3, r.peak_force), put(4, c.indentation), put(5, r.indentation);
  put(6, c.contact_duration), put(7, r.contact_duration), put(8, c.rebound_speed);
  put(9, r.rebound_speed), put(10, c.approach_speed), put(11, e.peak_force);
  put(12, e.indentation), put(13, e.contact_duration), put(14, e.rebound_speed);
  s.run();
}

namespace {

study::ModelTiming timing_from_row(const Statement& q, int first) {
  study::ModelTiming t;
  t.verdict = q.column_text(first);
  t.steps = static_cast<long>(q.column_int(first + 1));
  t.wall_seconds = q.column_double(first + 2);
  t.average_iteration_seconds = q.column_double(first + 3);
  t.initial_stable_dt = q.column_double(first + 4);
  return t;
}

}  // namespace

std::vector<study::PointMetrics> StudyStore::load_metrics() const {
  Statement q(*connection_, R"sql(
    SELECT gp.point_index, gp.content_hash, gp.modulus_ratio, gp.length_ratio,
           gp.kinetic_energy, gp.other_axes,
           m.usable, m.excluded_reason, m.cumulative_u_mean, m.cumulative_u_max,
           m.cumulative_kinetic_energy, m.final_u_mean, m.final_u_max, m.final_kinetic_energy,
           m.nt_ccm, m.nt_rigid, m.tr_ccm, m.tr_rigid, m.rtr,
           m.w_u_mean, m.w_u_max, m.w_kinetic_energy, m.t_final,
           c.status, c.steps, c.wall_seconds, c.average_iteration_seconds, c.initial_stable_dt,
           r.status, r.steps, r.wall_seconds, r.average_iteration_seconds, r.initial_stable_dt,
           m.tr_ccm_thesis_estimate, m.tr_rigid_thesis_estimate, m.rtr_thesis_estimate,
           m.peak_force_ccm, m.peak_force_rigid, m.indentation_ccm, m.indentation_rigid,
           m.contact_duration_ccm, m.contact_duration_rigid, m.rebound_speed_ccm,
           m.rebound_speed_rigid, m.approach_speed, m.error_peak_force, m.error_indentation,
           m.error_contact_duration, m.error_rebound_speed
    FROM metrics m JOIN grid_points gp ON gp.id = m.grid_point_id
    LEFT JOIN runs c ON c.grid_point_id = gp.id AND c.model = 'ccm'
    LEFT JOIN runs r ON r.grid_point_id = gp.id AND r.model = 'rigid'
    WHERE gp.study_id = ?1 ORDER BY gp.point_index)sql");
  q.bind(1, study_id());
  std::vector<study::PointMetrics> out;
  while (q.step()) {
    study::PointMetrics m;
    m.point = point_from_row(q, 0);
    m.usable = q.column_int(6) != 0;
    m.excluded_reason = q.column_text(7);
    auto v = [&](int column) { return q.column_optional_double(column).value_or(0.0); };
    m.cumulative = {v(8), v(9), v(10)};
    m.final_state = {v(11), v(12), v(13)};
    m.ccm = timing_from_row(q, 23);
    m.rigid = timing_from_row(q, 28);
    m.ccm.normalised_runtime = v(14);
    m.rigid.normalised_runtime = v(15);
    m.ccm.total_runtime = v(16);
    m.rigid.total_runtime = v(17);
    m.runtime_ratio = v(18);
    m.weighting = {v(19), v(20), v(21)};
    m.ccm.total_runtime_thesis_estimate = v(33);
    m.rigid.total_runtime_thesis_estimate = v(34);
    m.runtime_ratio_thesis_estimate = v(35);
    m.t_final = v(22);
    if (!q.is_null(48)) {  // the designer's metrics (schema 7 on)
      m.ccm_impact = study::ImpactQuantities{v(36), v(38), v(40), v(42), v(44)};
      m.rigid_impact = study::ImpactQuantities{v(37), v(39), v(41), v(43), v(44)};
      m.impact_errors = study::ImpactErrors{v(45), v(46), v(47), v(48)};
    }
    out.push_back(std::move(m));
  }
  return out;
}

void StudyStore::save_fits(const study::StudyFits& fits) {
  Transaction transaction(*connection_);
  Statement clear(*connection_, "DELETE FROM fits WHERE study_id = ?1");
  clear.bind(1, study_id());
  clear.run();
  Statement fit_row(*connection_, R"sql(
    INSERT INTO fits (study_id, metric, kinetic_energy, degree_log_er, degree_rls, r_squared,
                      loo_rmse, n_points, fitted_at, other_axes)
    VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10))sql");
  Statement term_row(*connection_,
                     "INSERT INTO fit_terms (fit_id, power_log_er, power_rls, coefficient) "
                     "VALUES (?1, ?2, ?3, ?4)");
  Statement point_row(*connection_,
                      "INSERT INTO fit_points (fit_id, grid_point_id, log10_er, rls, value) "
                      "VALUES (?1, ?2, ?3, ?4, ?5)");
  const std::string now = utc_now();
  for (const study::MetricFit& f : fits.fits) {
    const study::SurfaceFit& s = f.fit;
    fit_row.reset();
    fit_row.bind(1, study_id()).bind(2, study::to_string(f.metric)).bind(3, f.kinetic_energy);
    fit_row.bind(4, s.surface.degree.x).bind(5, s.surface.degree.y).bind(6, s.r_squared);
    fit_row.bind(7, s.loo_rmse).bind(8, static_cast<long long>(s.samples.size())).bind(9, now);
    fit_row.bind(10, other_axes_text(study::GridPoint{.other_axes = f.axes}));
    fit_row.run();
    const long long fit_id = connection_->last_insert_rowid();
    for (const study::SurfaceTerm& t : s.surface.terms) {
      term_row.reset();
      term_row.bind(1, fit_id).bind(2, t.power_x).bind(3, t.power_y).bind(4, t.coefficient);
      term_row.run();
    }
    for (const study::SurfaceSample& p : s.samples) {
      point_row.reset();
      point_row.bind(1, fit_id).bind(2, point_id_by_index(p.id)).bind(3, p.x).bind(4, p.y);
      point_row.bind(5, p.z);
      point_row.run();
    }
  }
  transaction.commit();
}

namespace {

void load_terms(Connection& c, long long fit_id, study::PolynomialSurface& surface) {
  Statement q(c,
              "SELECT power_log_er, power_rls, coefficient FROM fit_terms WHERE fit_id = ?1 "
              "ORDER BY power_log_er, power_rls");
  q.bind(1, fit_id);
  while (q.step())
    surface.terms.push_back(
        {static_cast<int>(q.column_int(0)), static_cast<int>(q.column_int(1)), q.column_double(2)});
}

void load_samples(Connection& c, long long fit_id, study::SurfaceFit& fit) {
  Statement q(c, R"sql(
    SELECT gp.point_index, fp.log10_er, fp.rls, fp.value FROM fit_points fp
    JOIN grid_points gp ON gp.id = fp.grid_point_id WHERE fp.fit_id = ?1
    ORDER BY gp.point_index)sql");
  q.bind(1, fit_id);
  while (q.step())
    fit.samples.push_back({q.column_double(1), q.column_double(2), q.column_double(3),
                           static_cast<int>(q.column_int(0))});
  bool first = true;
  for (const study::SurfaceSample& s : fit.samples) {
    fit.x_min = first ? s.x : std::min(fit.x_min, s.x);
    fit.x_max = first ? s.x : std::max(fit.x_max, s.x);
    fit.y_min = first ? s.y : std::min(fit.y_min, s.y);
    fit.y_max = first ? s.y : std::max(fit.y_max, s.y);
    first = false;
  }
}

}  // namespace

void StudyStore::save_grid(const StoredGrid& grid) {
  Statement row(*connection_, R"sql(
    INSERT INTO study_grids (study_id, source, grid_text, saved_at) VALUES (?1, ?2, ?3, ?4)
    ON CONFLICT (study_id) DO UPDATE SET source = ?2, grid_text = ?3, saved_at = ?4)sql");
  row.bind(1, study_id()).bind(2, grid.source).bind(3, grid.text).bind(4, utc_now());
  row.run();
}

std::optional<StoredGrid> StudyStore::load_grid() const {
  Statement q(*connection_, "SELECT source, grid_text FROM study_grids WHERE study_id = ?1");
  q.bind(1, study_id());
  if (!q.step()) return std::nullopt;
  return StoredGrid{q.column_text(0), q.column_text(1)};
}

study::StudyFits StudyStore::load_fits() const {
  study::StudyFits out;
  Statement q(*connection_, R"sql(
    SELECT id, metric, kinetic_energy, degree_log_er, degree_rls, r_squared, loo_rmse, other_axes
    FROM fits WHERE study_id = ?1 ORDER BY other_axes, kinetic_energy, id)sql");
  q.bind(1, study_id());
  while (q.step()) {
    const auto metric = study::metric_from_string(q.column_text(1));
    if (!metric) throw StoreError(file_.string() + ": unknown fit metric " + q.column_text(1));
    study::MetricFit f;
    f.metric = *metric;
    f.kinetic_energy = q.column_double(2);
    f.fit.surface.degree = {static_cast<int>(q.column_int(3)), static_cast<int>(q.column_int(4))};
    f.fit.r_squared = q.column_double(5);
    f.fit.loo_rmse = q.column_double(6);
    f.axes = other_axes_from_text(q.column_text(7));
    load_terms(*connection_, q.column_int(0), f.fit.surface);
    load_samples(*connection_, q.column_int(0), f.fit);
    out.fits.push_back(std::move(f));
  }
  for (const study::PointMetrics& m : load_metrics())
    if (!m.usable)
      out.excluded.push_back({m.point.index, m.point.kinetic_energy, m.excluded_reason});
  return out;
}

}  // namespace ccm::db
