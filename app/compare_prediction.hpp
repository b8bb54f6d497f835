// What a study store predicts for a scene `ccm compare` ran (docs/compare.md, "What a study
// predicts"): the scene's own groups (run/compare/scene_groups.hpp) carried onto the study's
// grid through the dimensionless ones (ER, RLS, KE* = KE / (E_A L_A^3) at the grid's E_A and
// L_A), the study's recommendation there, whether each group lies inside the grid's range, and
// whether the prediction agrees with the measured answer.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "run/compare/scene_comparison.hpp"
#include "run/compare/scene_groups.hpp"
#include "study/recommend/recommendation.hpp"

namespace ccm {

struct ComparePrediction {
  GroupsOrReason groups;
  // The query on the grid: ER and RLS as they are, KE = KE* E_A,grid L_A,grid^3 [J].
  double er = 0.0, rls = 0.0, ke = 0.0;
  double grid_density_ratio = 0.0;    // the grid's, or its density_ratio level nearest the scene's
  std::optional<double> grid_window;  // none: the store compares whole impacts
  std::vector<std::string> outside;   // each group outside the grid's range, with both
  std::optional<study::Recommendation> recommendation;
  std::optional<bool> agrees;  // the predicted model is the measured one
  std::string why_not;         // when it is not: which half of the rule differs, with both values
  std::string note;            // why there is no prediction (no store, no groups, no fits)
};

// The store a prediction comes from: --db when given, else the reference store ccm ships when
// it is installed, else the main job's store (`fallback`).
std::filesystem::path prediction_store(const std::filesystem::path& db,
                                       const std::filesystem::path& fallback);

// `whole_impact`: the scene ends after separation. A store of whole impacts is compared on whole
// impacts (no window to match); a fixed-window store by its window.
ComparePrediction predict_for_scene(const std::filesystem::path& db, GroupsOrReason groups,
                                    const ComparisonOutcome& measured, double max_error,
                                    bool whole_impact);

// Which half of the rule (docs/recommendation.md) a prediction and the measured answer differ on,
// with both values: the rigid model's accuracy (its largest final-state error against the max
// error) or its cost (RTR against 1); empty when they do not differ.
std::string why_they_differ(const study::Recommendation& predicted,
                            const ComparisonOutcome& measured, double max_error);

void print_prediction(const std::filesystem::path& db, const ComparePrediction& p);
nlohmann::json prediction_json(const std::filesystem::path& db, const ComparePrediction& p);

}  // namespace ccm
