#include "app/study_tables.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

#include "study/recommend/recommendation.hpp"

namespace ccm {
namespace {

// The fitted answer and its flag: "ok", "UNRELIABLE" (the fits' leave-one-out error exceeds
// the decision margin) or "DIFFERS" (the fitted surfaces give the other model here).
std::pair<std::string, std::string> fitted_columns(const study::PointDecision& d) {
  if (!d.fitted) return {"-", "no fit"};
  const auto model = std::string(study::to_string(d.fitted->model));
  if (d.fitted->measured_disagrees) return {model, "DIFFERS"};
  return {model, d.fitted->reliability.reliable ? "ok" : "UNRELIABLE"};
}

double largest(const study::ArtifactErrors& e) {
  return std::max({e.u_mean, e.u_max, e.kinetic_energy});
}

}  // namespace

void print_point_table(std::FILE* out, const std::vector<study::PointMetrics>& points,
                       const study::StudyFits& fits, double max_error) {
  fmt::print(out,
             "\nGrid points: final-state errors of rigid against CCM (eqs. 2.37-2.39); RTR = "
             "measured cost ratio TR_ccm/TR_rigid (CPU seconds of the step loops; used by every "
             "decision); RTR est. = the thesis's t_f AIR/ISTS ratio with the structural initial "
             "step (2.40-2.43; for comparison only, never decides); w = error/RTR (largest; "
             "informational); use = the rule on the measured values, fit = on the fitted "
             "surfaces\n{}\n",
             study::decision_rule_text(max_error));
  fmt::print(out,
             "{:>8} {:>5} {:>6}  {:>9} {:>9}  {:>8} {:>8} {:>8}  {:>9} {:>9} {:>9}  {:>9}  {:>5} "
             "{:>5} {}\n",
             "ER", "RLS", "KE[J]", "ccm", "rigid", "e_umean", "e_umax", "e_KE", "RTR", "RTR est.",
             "w_max", "wall[s]", "use", "fit", "flag");
  const std::vector<study::PointDecision> decisions =
      study::decide_grid_points(fits, points, max_error);
  std::size_t next = 0;
  for (const auto& m : points) {
    const auto& p = m.point;
    std::string extra;
    for (const auto& [name, value] : study::fit_axes(p))
      extra += fmt::format(" {}={:g}", name, value);
    fmt::print(out, "{:>8.0e} {:>5.2f} {:>6g}  {:>9} {:>9}  ", p.modulus_ratio, p.length_ratio,
               p.kinetic_energy, m.ccm.verdict, m.rigid.verdict);
    if (next >= decisions.size() || decisions[next].point != &m) {
      fmt::print(out, "left out of the fits: {}{}\n", m.excluded_reason, extra);
      continue;
    }
    const study::PointDecision& d = decisions[next++];
    const auto [fitted, flag] = fitted_columns(d);
    fmt::print(out,
               "{:>8.3f} {:>8.3f} {:>8.3f}  {:>9.3g} {:>9.3g} {:>9.3g}  {:>9.3g}  {:>5} {:>5} "
               "{}{}\n",
               m.final_state.u_mean, m.final_state.u_max, m.final_state.kinetic_energy,
               m.runtime_ratio, m.runtime_ratio_thesis_estimate, largest(m.weighting),
               m.ccm.wall_seconds + m.rigid.wall_seconds, study::to_string(d.measured.model),
               fitted, flag, extra);
  }
  for (const auto& note : fits.notes) fmt::print(out, "note: {}\n", note);
}

void print_convergence_table(std::FILE* out, const std::vector<study::ConvergenceRow>& rows) {
  if (rows.empty()) return;
  fmt::print(out,
             "\nConvergence: final-state errors against the finest CCM run of each point, next "
             "to each run's wall time\n");
  fmt::print(out, "{:>8} {:>5} {:>6} {:>6} {:>6} {:>8}  {:>8} {:>8} {:>8}  {:>9}\n", "ER", "RLS",
             "KE[J]", "model", "scale", "elements", "e_umean", "e_umax", "e_KE", "wall[s]");
  for (const auto& r : rows) {
    const auto& p = r.point;
    fmt::print(out, "{:>8.0e} {:>5.2f} {:>6g} {:>6} {:>6.2f} {:>8}  ", p.modulus_ratio,
               p.length_ratio, p.kinetic_energy, study::to_string(r.model), study::mesh_scale(p),
               r.n_elements);
    if (r.reference)
      fmt::print(out, "{:>26}  ", "(reference)");
    else if (!r.usable)
      fmt::print(out, "{:>26}  ", "(not comparable)");
    else
      fmt::print(out, "{:>8.4f} {:>8.4f} {:>8.4f}  ", r.final_state.u_mean, r.final_state.u_max,
                 r.final_state.kinetic_energy);
    fmt::print(out, "{:>9.3g}\n", r.wall_seconds);
  }
}

}  // namespace ccm

namespace ccm {

void print_trend_table(std::FILE* out, const std::vector<study::TrendRow>& trends,
                       const std::vector<study::PointMetrics>& points) {
  if (trends.empty()) return;
  fmt::print(out,
             "\nThesis trends (2.8): largest artifact KE gap over the run / rigid peak (thesis: "
             "< 0.15 at high ER); CCM / rigid at t_f of the artifact KE, mean and max "
             "displacement (thesis at ER 1, RLS 0.5, KE 100: 0.41, 0.65, 0.61); RTR measured\n");
  fmt::print(out, "{:>8} {:>5} {:>6}  {:>8}  {:>8} {:>8} {:>8}  {:>9}\n", "ER", "RLS", "KE[J]",
             "KE_gap", "KE c/r", "umean", "umax", "RTR");
  for (const auto& t : trends) {
    const auto& p = t.point;
    double rtr = 0.0;
    for (const auto& m : points)
      if (m.point.index == p.index) rtr = m.runtime_ratio;
    fmt::print(out, "{:>8.0e} {:>5.2f} {:>6g}  {:>8.3f}  {:>8.3f} {:>8.3f} {:>8.3f}  {:>9.3g}\n",
               p.modulus_ratio, p.length_ratio, p.kinetic_energy, t.ke_gap, t.ke_ratio,
               t.u_mean_ratio, t.u_max_ratio, rtr);
  }
}

}  // namespace ccm
