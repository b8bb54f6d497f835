#include "app/compare_prediction.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "app/data_paths.hpp"
#include "app/stored_grid.hpp"
#include "app/study_store_open.hpp"
#include "study/fit/study_fits.hpp"

namespace ccm {
namespace {

void check_range(const char* name, double value, const std::vector<double>& levels,
                 std::vector<std::string>& outside) {
  if (levels.empty()) return;
  const auto [lo, hi] = std::minmax_element(levels.begin(), levels.end());
  if (value < *lo || value > *hi)
    outside.push_back(
        fmt::format("{} {:.3g} is outside the grid's [{:.3g}, {:.3g}]", name, value, *lo, *hi));
}

// A group the grid holds at one value: outside when more than 10 % from it.
void check_value(const char* name, double value, double grid, std::vector<std::string>& outside) {
  if (std::abs(value - grid) > 0.1 * std::abs(grid))
    outside.push_back(fmt::format(
        "{} {:.3g} differs from the grid's {:.3g} (the study holds it fixed)", name, value, grid));
}

}  // namespace

std::string why_they_differ(const study::Recommendation& r, const ComparisonOutcome& measured,
                            double max_error) {
  const study::Decision& predicted = r.decision;
  const study::Decision& found = measured.decision;
  std::string why;
  if (predicted.rigid_within_error != found.rigid_within_error)
    why = fmt::format(
        "on accuracy: the study predicts the rigid model's largest final-state error at {:.3g}, "
        "this scene measured {:.3g} (max error {:.3g}); the sphere-on-plate grid's errors hold "
        "for this design only as far as its groups do",
        predicted.worst_error, found.worst_error, max_error);
  if (predicted.rigid_cheaper != found.rigid_cheaper)
    why += fmt::format(
        "{}on cost: the study predicts RTR {:.3g}, this scene measured {:.3g}; a cost ratio "
        "follows which body and which contact law set the step (the grid's rigid model is its "
        "own penalty sphere, this scene's rigid variant keeps the scene's contact), so it does "
        "not carry over from the grid",
        why.empty() ? "" : "; and ", r.predicted.runtime_ratio, measured.cost_ratio);
  return why.empty() ? why : "they differ " + why;
}

std::filesystem::path prediction_store(const std::filesystem::path& db,
                                       const std::filesystem::path& fallback) {
  if (!db.empty()) return db;
  const std::filesystem::path reference = default_data_file(kReferenceStore);
  if (!reference.empty() && std::filesystem::is_regular_file(reference)) return reference;
  return fallback;
}

namespace {

// The grid's density_ratio level nearest the scene's (in log), or its one impactor density.
double grid_density_ratio(const study::GridSpec& grid, double scene_ratio,
                          study::AxisLevels& axes) {
  const auto levels = grid.other_axes.find("density_ratio");
  if (levels == grid.other_axes.end()) return grid.impactor.rho / grid.artifact.rho;
  double best = levels->second.front();
  for (double v : levels->second)
    if (std::abs(std::log(v / scene_ratio)) < std::abs(std::log(best / scene_ratio))) best = v;
  axes["density_ratio"] = best;
  return best;
}

}  // namespace

ComparePrediction predict_for_scene(const std::filesystem::path& db, GroupsOrReason groups,
                                    const ComparisonOutcome& measured, double max_error,
                                    bool whole_impact) {
  ComparePrediction p;
  p.groups = std::move(groups);
  if (!p.groups.groups) {
    p.note = p.groups.reason;
    return p;
  }
  if (!std::filesystem::is_regular_file(db)) {
    p.note = fmt::format(
        "no study store at {} (the main job writes it: scripts/run.sh, or `ccm study run`)",
        db.string());
    return p;
  }
  const auto store = open_study_store(db);
  const auto grid = stored_grid_spec(*store);
  if (!grid) {
    p.note =
        fmt::format("{}: the store keeps no grid file, so its scales are unknown", db.string());
    return p;
  }
  const SceneGroups& g = *p.groups.groups;
  const study::ArtifactSpec& a = grid->artifact;
  p.er = g.modulus_ratio;
  p.rls = g.length_ratio;
  p.ke = g.kinetic_energy_star * a.E * a.length * a.length * a.length;
  study::AxisLevels axes;
  p.grid_density_ratio = grid_density_ratio(*grid, g.density_ratio, axes);
  if (!grid->time.end_after_separation)
    p.grid_window = (grid->time.end - grid->time.contact_time) * std::sqrt(a.E / a.rho) / a.length;
  check_range("ER", p.er, grid->modulus_ratios, p.outside);
  check_range("RLS", p.rls, grid->length_ratios, p.outside);
  check_range("KE (from KE*)", p.ke, grid->kinetic_energies, p.outside);
  check_value("density ratio", g.density_ratio, p.grid_density_ratio, p.outside);
  if (p.grid_window && g.window)
    check_value("window (t_f - t_c) c_A / L_A", *g.window, *p.grid_window, p.outside);
  if (!p.grid_window && !whole_impact)
    p.outside.push_back(
        "window: the store compares whole impacts, this scene ends at its [time] end (add "
        "[time] end_after_separation to compare like with like)");
  const std::vector<study::PointMetrics> points = store->load_metrics();
  const study::StudyFits fits = study::fit_study(points);
  if (fits.fits.empty()) {
    p.note = fmt::format("{}: the study has no fitted surfaces yet", db.string());
    return p;
  }
  study::RecommendQuery q;
  q.modulus_ratio = p.er;
  q.length_ratio = p.rls;
  q.kinetic_energy = p.ke;
  q.max_error = max_error;
  q.axes = axes;
  try {
    p.recommendation = study::recommend(fits, points, q);
  } catch (const std::exception& e) {
    p.note = fmt::format("the study cannot predict here: {}", e.what());
    return p;
  }
  if (measured.unusable.empty()) {
    p.agrees = p.recommendation->model == measured.decision.model;
    if (!*p.agrees) p.why_not = why_they_differ(*p.recommendation, measured, max_error);
  }
  return p;
}

void print_prediction(const std::filesystem::path& db, const ComparePrediction& p) {
  fmt::print("\n  what the study {} predicts for this scene:\n", db.string());
  if (const auto& g = p.groups.groups) {
    fmt::print(
        "    groups: impactor '{}' (E {:.4g} Pa, rho {:.4g}, D_I {:.4g} m = diameter of the "
        "sphere of its mass, m {:.4g} kg, |v| {:.4g} m/s), artifact '{}' (E {:.4g} Pa, rho {:.4g}, "
        "L_A {:.4g} m = its largest extent)\n",
        g->impactor, g->E_I, g->rho_I, g->D_I, g->m_I, g->relative_speed, g->artifact, g->E_A,
        g->rho_A, g->L_A);
    fmt::print("    ER {:.4g}, RLS {:.4g}, KE {:.4g} J, KE* {:.4g}, density ratio {:.4g}{}\n",
               g->modulus_ratio, g->length_ratio, g->kinetic_energy, g->kinetic_energy_star,
               g->density_ratio,
               g->window ? fmt::format(", window {:.4g}", *g->window) : std::string());
  }
  if (!p.note.empty()) {
    fmt::print("    no prediction: {}\n", p.note);
    return;
  }
  fmt::print("    on the grid: ER {:.4g}, RLS {:.4g}, KE {:.4g} J\n", p.er, p.rls, p.ke);
  for (const std::string& o : p.outside) fmt::print("    outside: {}\n", o);
  if (!p.recommendation) return;
  const study::Recommendation& r = *p.recommendation;
  fmt::print("    predicts: {}{} ({})\n",
             r.model == study::ImpactModel::rigid ? "rigid is good enough" : "keep it deformable",
             r.reliability.reliable ? "" : ", UNRELIABLE", r.reason);
  for (const std::string& w : r.warnings) fmt::print("    warning: {}\n", w);
  if (p.agrees)
    fmt::print("    {} the measured answer\n", *p.agrees ? "agrees with" : "DISAGREES with");
  if (!p.why_not.empty()) fmt::print("    why: {}\n", p.why_not);
}

nlohmann::json prediction_json(const std::filesystem::path& db, const ComparePrediction& p) {
  nlohmann::json j = {{"db", db.string()}};
  if (const auto& g = p.groups.groups)
    j["groups"] = {{"impactor", g->impactor},
                   {"artifact", g->artifact},
                   {"E_I", g->E_I},
                   {"E_A", g->E_A},
                   {"rho_I", g->rho_I},
                   {"rho_A", g->rho_A},
                   {"D_I", g->D_I},
                   {"L_A", g->L_A},
                   {"m_I", g->m_I},
                   {"relative_speed", g->relative_speed},
                   {"er", g->modulus_ratio},
                   {"rls", g->length_ratio},
                   {"ke", g->kinetic_energy},
                   {"ke_star", g->kinetic_energy_star},
                   {"density_ratio", g->density_ratio},
                   {"window", g->window ? nlohmann::json(*g->window) : nlohmann::json()}};
  if (!p.note.empty()) {
    j["note"] = p.note;
    return j;
  }
  j["on_grid"] = {{"er", p.er},
                  {"rls", p.rls},
                  {"ke", p.ke},
                  {"density_ratio", p.grid_density_ratio},
                  {"window", p.grid_window ? nlohmann::json(*p.grid_window) : nlohmann::json()},
                  {"whole_impacts", !p.grid_window.has_value()}};
  j["outside_grid"] = p.outside;
  if (p.recommendation) {
    const study::Recommendation& r = *p.recommendation;
    j["model"] = r.model == study::ImpactModel::rigid ? "rigid" : "deformable";
    j["reliable"] = r.reliability.reliable;
    j["reason"] = r.reason;
    j["warnings"] = r.warnings;
    j["loo_rmse"] = {{"u_mean", r.predicted.uncertainty.final_state.u_mean},
                     {"u_max", r.predicted.uncertainty.final_state.u_max},
                     {"kinetic_energy", r.predicted.uncertainty.final_state.kinetic_energy},
                     {"log10_runtime_ratio", r.predicted.uncertainty.log10_runtime_ratio}};
  }
  if (p.agrees) j["agrees_with_measured"] = *p.agrees;
  if (!p.why_not.empty()) j["why_not"] = p.why_not;
  return j;
}

}  // namespace ccm
