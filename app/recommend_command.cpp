// `ccm recommend --db FILE --er X --rls Y --ke Z [--max-error E] [--axis NAME=VALUE]... [--json]`:
// which impactor model to use at a design point, by the one decision rule
// (study/recommend/decision_rule.hpp) on the surfaces fitted to the study's measured points,
// whether the answer can be trusted, the nearest measured points and the modelling choices.
#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "app/command_errors.hpp"
#include "app/data_paths.hpp"
#include "app/json_output.hpp"
#include "app/run_command.hpp"
#include "app/stored_grid.hpp"
#include "app/study_commands.hpp"
#include "app/study_store_open.hpp"
#include "study/recommend/modelling_choices.hpp"
#include "study/recommend/recommendation.hpp"

namespace ccm {
namespace {

// "damping=1" -> {"damping", 1}; bad input names the argument.
study::AxisLevels parse_axes(const std::vector<std::string>& items) {
  study::AxisLevels axes;
  for (const std::string& item : items) {
    const auto eq = item.find('=');
    char* end = nullptr;
    const double value = eq == std::string::npos ? 0.0 : std::strtod(item.c_str() + eq + 1, &end);
    if (eq == std::string::npos || eq == 0 || end == item.c_str() + eq + 1 || *end != '\0' ||
        !std::isfinite(value))
      throw std::invalid_argument(
          fmt::format("--axis {}: expected NAME=VALUE with a number, e.g. damping=1", item));
    if (!axes.emplace(item.substr(0, eq), value).second)
      throw std::invalid_argument(fmt::format("--axis {}: axis given twice", item.substr(0, eq)));
  }
  return axes;
}

nlohmann::json errors_json(const study::ArtifactErrors& e) {
  return {{"u_mean", e.u_mean}, {"u_max", e.u_max}, {"kinetic_energy", e.kinetic_energy}};
}

nlohmann::json groups_json(const std::vector<study::GroupRange>& groups) {
  nlohmann::json out = nlohmann::json::array();
  for (const study::GroupRange& g : groups)
    out.push_back({{"group", g.name},
                   {"value", g.value},
                   {"studied_min", g.low},
                   {"studied_max", g.high},
                   {"inside", g.inside()}});
  return out;
}

// The designer's errors (docs/metrics.md), or null when the point's runs did not keep them.
nlohmann::json impact_errors_json(const std::optional<study::ImpactErrors>& e) {
  if (!e) return nullptr;
  return {{"peak_force", e->peak_force},
          {"indentation", e->indentation},
          {"contact_duration", e->contact_duration},
          {"rebound_speed", e->rebound_speed}};
}

nlohmann::json nearest_json(const std::vector<study::NearbyPoint>& points) {
  nlohmann::json out = nlohmann::json::array();
  for (const study::NearbyPoint& p : points)
    out.push_back({{"point_index", p.point.index},
                   {"er", p.point.modulus_ratio},
                   {"rls", p.point.length_ratio},
                   {"ke", p.point.kinetic_energy},
                   {"distance_grid_spacings", p.distance},
                   {"final_state_error", errors_json(p.measured.final_state)},
                   {"runtime_ratio", p.measured.runtime_ratio},
                   {"weighting", errors_json(p.weighting)},
                   {"model", study::to_string(p.decision.model)},
                   {"impact_errors", impact_errors_json(p.impact_errors)}});
  return out;
}

nlohmann::json recommendation_json(const RecommendArgs& q, const study::Recommendation& r,
                                   const std::optional<study::GridSpec>& grid) {
  const auto& p = r.predicted;
  return {
      {"query",
       {{"er", q.er}, {"rls", q.rls}, {"ke", q.ke}, {"max_error", q.max_error}, {"axes", r.axes}}},
      {"model", study::to_string(r.model)},
      {"rule", r.rule},
      {"reason", r.reason},
      {"reliable", r.reliability.reliable},
      {"unreliable_reasons", r.reliability.reasons},
      {"rigid_within_error", r.decision.rigid_within_error},
      {"rigid_cheaper", r.decision.rigid_cheaper},
      {"at_grid_point", r.at_grid_point},
      {"measured_disagrees", r.measured_disagrees},
      {"predicted",
       {{"final_state_error", errors_json(p.final_state)},
        {"final_state_error_loo_rmse", errors_json(p.uncertainty.final_state)},
        {"runtime_ratio", p.runtime_ratio},
        {"log10_runtime_ratio_loo_rmse", p.uncertainty.log10_runtime_ratio},
        {"weighting", errors_json(p.weighting)}}},
      {"clamped", r.clamped},
      {"nearest_measured_points", nearest_json(r.nearest)},
      {"kinetic_energy_levels_used", r.kinetic_energy_levels_used},
      {"modelling_choices", modelling_choices_json(grid, r.axes)},
      {"warnings", r.warnings},
      {"groups", groups_json(r.groups)}};
}

// Which store and study an answer came from.
struct StoreSource {
  std::filesystem::path path;
  std::string study;
  bool reference = false;  // the shipped reference store, not --db
};

void print_nearest(const std::vector<study::NearbyPoint>& points) {
  fmt::print("nearest measured points (distance in grid spacings of log10 ER, RLS, KE):\n");
  for (const study::NearbyPoint& p : points) {
    const auto& e = p.measured.final_state;
    fmt::print(
        "  point {}: ER {:g}, RLS {:g}, KE {:g} J (distance {:.2f}): errors u_mean {:.3f}, u_max "
        "{:.3f}, KE {:.3f}; RTR {:.3g}; w max {:.3g}; measured answer {}\n",
        p.point.index, p.point.modulus_ratio, p.point.length_ratio, p.point.kinetic_energy,
        p.distance, e.u_mean, e.u_max, e.kinetic_energy, p.measured.runtime_ratio,
        std::max({p.weighting.u_mean, p.weighting.u_max, p.weighting.kinetic_energy}),
        study::to_string(p.decision.model));
    if (const auto& i = p.impact_errors)
      fmt::print(
          "    designer's errors (docs/metrics.md): peak force {:.3f}, indentation {:.3f}, "
          "contact duration {:.3f}, rebound speed {:.3f}\n",
          i->peak_force, i->indentation, i->contact_duration, i->rebound_speed);
  }
}

void print_choices(const std::optional<study::GridSpec>& grid, const study::AxisLevels& axes) {
  if (!grid) {
    fmt::print("{}\n", kNoStoredGrid);
    return;
  }
  fmt::print("modelling choices (grid file {}):\n", grid->source.string());
  for (const study::ModellingChoice& c : study::modelling_choices(*grid, axes))
    fmt::print("  {}\n", c.text());
}

void print_recommendation(const RecommendArgs& q, const study::Recommendation& r,
                          const std::optional<study::GridSpec>& grid) {
  const auto& p = r.predicted;
  const auto& u = p.uncertainty;
  fmt::print("design point: ER = {:g}, RLS = {:g}, KE = {:g} J{}{}\n", q.er, q.rls, q.ke,
             r.axes.empty() ? "" : ", ", study::axes_text(r.axes));
  std::string groups;
  for (const study::GroupRange& g : r.groups) groups += (groups.empty() ? "" : ", ") + g.text();
  fmt::print("groups: {}\n", groups);
  fmt::print("{}\n", r.rule);
  fmt::print("use: {}{}\nwhy: {}\n", study::to_string(r.model),
             r.reliability.reliable ? "" : " (UNRELIABLE: see below)", r.reason);
  for (const auto& reason : r.reliability.reasons) fmt::print("unreliable: {}\n", reason);
  fmt::print(
      "predicted final-state error of rigid vs CCM: u_mean {:.3f} (leave-one-out error {:.3f}), "
      "u_max {:.3f} ({:.3f}), KE {:.3f} ({:.3f})\n",
      p.final_state.u_mean, u.final_state.u_mean, p.final_state.u_max, u.final_state.u_max,
      p.final_state.kinetic_energy, u.final_state.kinetic_energy);
  fmt::print(
      "predicted cost ratio RTR = TR_ccm / TR_rigid: {:.3g} (leave-one-out error {:.2f} "
      "decades)\n",
      p.runtime_ratio, u.log10_runtime_ratio);
  fmt::print(
      "predicted weighting w = error / RTR (informational): u_mean {:.3g}, u_max {:.3g}, KE "
      "{:.3g}\n",
      p.weighting.u_mean, p.weighting.u_max, p.weighting.kinetic_energy);
  for (const auto& c : r.clamped) fmt::print("clamped: {}\n", c);
  print_nearest(r.nearest);
  print_choices(grid, r.axes);
  for (const auto& w : r.warnings) fmt::print("warning: {}\n", w);
}

}  // namespace

// The store a recommendation reads: --db, or the reference store ccm ships (the whole-impact
// grid over the users' regime, docs/recommendation.md "The reference store").
std::filesystem::path recommendation_store(const RecommendArgs& args) {
  if (!args.db.empty()) return args.db;
  const std::filesystem::path reference = default_data_file(kReferenceStore);
  if (reference.empty()) throw StudyInputError(missing_data_message("--db"));
  if (!std::filesystem::is_regular_file(reference))
    throw StudyInputError(fmt::format(
        "no --db given and no reference store at {} (scripts/build-reference-store.sh builds it "
        "from scenes/grids/whole-impacts.toml; or pass --db FILE, a store of `ccm study run`)",
        reference.string()));
  return reference;
}

int recommend_command(const RecommendArgs& args) {
  return run_reporting_errors([&] {
    if (!(std::isfinite(args.max_error) && args.max_error >= 0.0))
      throw StudyInputError(
          fmt::format("--max-error {}: must be a non-negative number", args.max_error));
    study::RecommendQuery query;
    query.modulus_ratio = args.er;
    query.length_ratio = args.rls;
    query.kinetic_energy = args.ke;
    query.max_error = args.max_error;
    query.axes = parse_axes(args.axes);
    const std::filesystem::path db = recommendation_store(args);
    auto store = open_study_store(db);
    const std::vector<study::PointMetrics> measured = store->load_metrics();
    const study::StudyFits fits = study::fit_study(measured);
    if (fits.fits.empty())
      throw StudyInputError(db.string() +
                            ": the study has no fitted surfaces yet (no point with both runs "
                            "completed): finish `ccm study run` first");
    const auto grid = stored_grid_spec(*store);
    const study::Recommendation r = study::recommend(fits, measured, query);
    const StoreSource source{db, store->study_name(), args.db.empty()};
    if (args.json) {
      nlohmann::json j = recommendation_json(args, r, grid);
      j["store"] = {{"path", source.path.string()},
                    {"study", source.study},
                    {"reference", source.reference},
                    {"grid_file", grid ? grid->source.string() : ""}};
      print_json(j);
    } else {
      fmt::print("store: {} (study \"{}\"{})\n", source.path.string(), source.study,
                 source.reference ? ", the reference store ccm ships" : "");
      print_recommendation(args, r, grid);
    }
    return exit_code::completed;
  });
}

}  // namespace ccm
