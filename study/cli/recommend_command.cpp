// `ccm recommend --db FILE --er X --rls Y --ke Z [--max-error E] [--json]`: which impactor
// model to use at a design point, from the study's fitted surfaces, and why.
#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "study/cli/command_errors.hpp"
#include "study/cli/run_command.hpp"
#include "study/cli/study_commands.hpp"
#include "study/cli/study_store_open.hpp"
#include "study/recommend/recommendation.hpp"

namespace ccm {
namespace {

nlohmann::json errors_json(const study::ArtifactErrors& e) {
  return {{"u_mean", e.u_mean}, {"u_max", e.u_max}, {"kinetic_energy", e.kinetic_energy}};
}

nlohmann::json recommendation_json(const RecommendArgs& q, const study::Recommendation& r) {
  nlohmann::json query = {{"er", q.er}, {"rls", q.rls}, {"ke", q.ke}};
  if (q.max_error) query["max_error"] = *q.max_error;
  return {{"query", query},
          {"model", study::to_string(r.model)},
          {"reason", r.reason},
          {"predicted",
           {{"final_state_error", errors_json(r.predicted.final_state)},
            {"runtime_ratio", r.predicted.runtime_ratio},
            {"weighting", errors_json(r.predicted.weighting)}}},
          {"kinetic_energy_levels_used", r.kinetic_energy_levels_used},
          {"warnings", r.warnings}};
}

void print_recommendation(const RecommendArgs& q, const study::Recommendation& r) {
  const auto& p = r.predicted;
  fmt::print("design point: ER = {:g}, RLS = {:g}, KE = {:g} J\n", q.er, q.rls, q.ke);
  fmt::print("use: {}\nwhy: {}\n", study::to_string(r.model), r.reason);
  fmt::print(
      "predicted final-state error of rigid vs CCM: u_mean {:.3f}, u_max {:.3f}, KE {:.3f}\n",
      p.final_state.u_mean, p.final_state.u_max, p.final_state.kinetic_energy);
  fmt::print("predicted runtime ratio RTR = NT_ccm / NT_rigid: {:.3g}\n", p.runtime_ratio);
  fmt::print("predicted weighting w = error / RTR: u_mean {:.3g}, u_max {:.3g}, KE {:.3g}\n",
             p.weighting.u_mean, p.weighting.u_max, p.weighting.kinetic_energy);
  for (const auto& w : r.warnings) fmt::print("warning: {}\n", w);
}

}  // namespace

int recommend_command(const RecommendArgs& args) {
  return run_reporting_errors([&] {
    auto store = open_study_store(args.db);
    const study::StudyFits fits = store->load_fits();
    if (fits.fits.empty())
      throw StudyInputError(args.db.string() +
                            ": the study has no fitted surfaces yet (no point with both runs "
                            "completed): finish `ccm study run` first");
    study::RecommendQuery query;
    query.modulus_ratio = args.er;
    query.length_ratio = args.rls;
    query.kinetic_energy = args.ke;
    query.max_error = args.max_error;
    const study::Recommendation r = study::recommend(fits, query);
    if (args.json)
      fmt::print("{}\n", recommendation_json(args, r).dump(2));
    else
      print_recommendation(args, r);
    return exit_code::completed;
  });
}

}  // namespace ccm
