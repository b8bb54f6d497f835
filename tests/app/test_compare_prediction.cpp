// Why a study's prediction and `ccm compare`'s measured answer differ (app/compare_prediction.hpp):
// the half of the rule that differs, with both values.
#include <catch2/catch.hpp>

#include "app/compare_prediction.hpp"

using Catch::Contains;
using namespace ccm;

namespace {

study::Recommendation predicted(double worst_error, double rtr, double max_error) {
  study::Recommendation r;
  r.decision.worst_error = worst_error;
  r.decision.rigid_within_error = worst_error <= max_error;
  r.decision.rigid_cheaper = rtr > 1.0;
  r.predicted.runtime_ratio = rtr;
  return r;
}

ComparisonOutcome measured(double worst_error, double rtr, double max_error) {
  ComparisonOutcome m;
  m.cost_ratio = rtr;
  m.decision.worst_error = worst_error;
  m.decision.rigid_within_error = worst_error <= max_error;
  m.decision.rigid_cheaper = rtr > 1.0;
  return m;
}

}  // namespace

TEST_CASE("compare: why the prediction differs from the measured answer", "[compare]") {
  // Both accurate; the study predicts the rigid model dearer, the scene measured it cheaper.
  const std::string cost =
      why_they_differ(predicted(0.03, 0.42, 0.1), measured(0.02, 1.37, 0.1), 0.1);
  CHECK_THAT(cost, Contains("they differ on cost: the study predicts RTR 0.42, this scene measured "
                            "1.37"));
  CHECK_THAT(cost, Contains("does not carry over from the grid"));
  CHECK_THAT(cost, !Contains("accuracy"));
  // Both cheaper; the study predicts the rigid model off, the scene measured it accurate.
  const std::string accuracy =
      why_they_differ(predicted(0.13, 3.0, 0.1), measured(0.05, 2.0, 0.1), 0.1);
  CHECK_THAT(accuracy, Contains("they differ on accuracy: the study predicts the rigid model's "
                                "largest final-state error at 0.13, this scene measured 0.05 "
                                "(max error 0.1)"));
  CHECK_THAT(accuracy, !Contains("on cost"));
  // Both halves.
  const std::string both = why_they_differ(predicted(0.2, 0.5, 0.1), measured(0.05, 2.0, 0.1), 0.1);
  CHECK_THAT(both, Contains("on accuracy") && Contains("; and on cost"));
  // The same halves: nothing to explain.
  CHECK(why_they_differ(predicted(0.05, 2.0, 0.1), measured(0.04, 3.0, 0.1), 0.1).empty());
}
