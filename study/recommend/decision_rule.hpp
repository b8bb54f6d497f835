// The one rule that picks the impactor model (docs/recommendation.md), used on measured values
// (the study table, the report's per-point table) and on predicted values (`ccm recommend`,
// the report's map):
//
//   use the rigid model where its final-state error against CCM (eqs. 2.37-2.39) is within
//   max_error on every metric AND it is cheaper (RTR = TR_ccm / TR_rigid > 1); otherwise CCM.
//
// The weighting functions w = error / RTR (thesis 2.8, Fig. 2-29) are shown beside the answer,
// never used for it.
#pragma once

#include <span>
#include <string>

#include "records/grid_point.hpp"
#include "records/point_metrics.hpp"

namespace ccm::study {

// The error threshold of `ccm recommend`, `ccm report` and the study table when none is given.
inline constexpr double kDefaultMaxError = 0.1;

// What the rule reads: the rigid model's final-state errors against CCM and the cost ratio.
struct DecisionInputs {
  ArtifactErrors final_state;  // eqs. 2.37-2.39
  double runtime_ratio = 1.0;  // RTR = TR_ccm / TR_rigid, measured CPU stepping time
};

struct Decision {
  ImpactModel model = ImpactModel::ccm;
  bool rigid_within_error = false;  // every final-state error <= max_error
  bool rigid_cheaper = false;       // RTR > 1
  double worst_error = 0.0;         // the largest of the three final-state errors
};

Decision decide_model(const DecisionInputs& inputs, double max_error);
// The same rule on any number of final-state errors (`ccm compare`'s observables, docs/compare.md).
Decision decide_model(std::span<const double> final_state_errors, double runtime_ratio,
                      double max_error);

// The uncertainty of each input, in the units the rule compares: the errors' own units and
// decades of RTR (leave-one-out RMSE of the fitted surfaces).
struct DecisionUncertainty {
  ArtifactErrors final_state;
  double log10_runtime_ratio = 0.0;
};

// Whether the answer could flip within the inputs' uncertainty. Rigid flips when any one of its
// conditions can fail: an error within its uncertainty of max_error (|error - max_error| <=
// uncertainty) or |log10 RTR| <= its uncertainty. CCM flips only when every condition that fails
// can hold: each error above max_error within its uncertainty of it and, when RTR <= 1,
// |log10 RTR| within its uncertainty. `reasons` names each such margin with its numbers.
struct Reliability {
  bool reliable = true;
  std::vector<std::string> reasons;
};
Reliability decision_reliability(const DecisionInputs& inputs,
                                 const DecisionUncertainty& uncertainty, double max_error);

// The rule in one sentence with this threshold, printed with every answer.
std::string decision_rule_text(double max_error);

// Why: "rigid: every final-state error (u_mean 0.02, u_max 0.05, KE 0.08) is within 0.1 and
// CCM costs 12.3x the rigid model (RTR > 1)".
std::string decision_reason(const DecisionInputs& inputs, const Decision& decision,
                            double max_error);

}  // namespace ccm::study
