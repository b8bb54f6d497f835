// The one decision rule (study/recommend/decision_rule.hpp, docs/recommendation.md): rigid
// where every final-state error is within max_error AND RTR > 1; and when an answer could flip
// within the inputs' uncertainty.
#include <catch2/catch.hpp>
#include <string>

#include "study/recommend/decision_rule.hpp"

using namespace ccm::study;

namespace {

DecisionInputs inputs(double u_mean, double u_max, double ke, double rtr) {
  return {{u_mean, u_max, ke}, rtr};
}

DecisionUncertainty uncertainty(double errors, double log10_rtr) {
  return {{errors, errors, errors}, log10_rtr};
}

bool mentions(const Reliability& r, const std::string& text) {
  for (const auto& reason : r.reasons)
    if (reason.find(text) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_CASE("the rule: rigid only when within the error on every metric and cheaper", "[recommend]") {
  CHECK(decide_model(inputs(0.05, 0.08, 0.02, 10.0), 0.1).model == ImpactModel::rigid);
  // "Within" includes the threshold itself.
  CHECK(decide_model(inputs(0.05, 0.1, 0.02, 10.0), 0.1).model == ImpactModel::rigid);
  // One metric above the threshold is enough for CCM.
  const Decision over = decide_model(inputs(0.05, 0.08, 0.1001, 10.0), 0.1);
  CHECK(over.model == ImpactModel::ccm);
  CHECK_FALSE(over.rigid_within_error);
  CHECK(over.rigid_cheaper);
  CHECK(over.worst_error == 0.1001);
  // Accurate but not cheaper: CCM (at RTR = 1 the rigid model saves nothing).
  const Decision even = decide_model(inputs(0.0, 0.0, 0.0, 1.0), 0.1);
  CHECK(even.model == ImpactModel::ccm);
  CHECK(even.rigid_within_error);
  CHECK_FALSE(even.rigid_cheaper);
  CHECK(decide_model(inputs(0.0, 0.0, 0.0, 1.0001), 0.1).model == ImpactModel::rigid);
  CHECK(decide_model(inputs(0.0, 0.0, 0.0, 0.2), 0.1).model == ImpactModel::ccm);
}

TEST_CASE("the rule and its reason are printed with the numbers", "[recommend]") {
  CHECK(decision_rule_text(0.1).find("within 0.1 on every metric") != std::string::npos);
  CHECK(decision_rule_text(0.1).find("RTR = TR_ccm / TR_rigid > 1") != std::string::npos);
  const DecisionInputs in = inputs(0.05, 0.08, 0.02, 0.5);
  const std::string why = decision_reason(in, decide_model(in, 0.1), 0.1);
  CHECK(why.rfind("ccm:", 0) == 0);
  CHECK(why.find("all within 0.1") != std::string::npos);
  CHECK(why.find("CCM costs 0.5x the rigid model: it is not dearer") != std::string::npos);
}

TEST_CASE("a rigid answer is unreliable when any one condition is within its uncertainty",
          "[recommend]") {
  const DecisionInputs in = inputs(0.02, 0.08, 0.03, 100.0);  // u_max 0.02 below 0.1
  CHECK(decision_reliability(in, uncertainty(0.019, 0.5), 0.1).reliable);
  const Reliability close_error = decision_reliability(in, uncertainty(0.021, 0.5), 0.1);
  CHECK_FALSE(close_error.reliable);
  REQUIRE(close_error.reasons.size() == 1);
  CHECK(mentions(close_error, "u_max = 0.08 is 0.02 from the threshold 0.1"));
  // log10 100 = 2 decades from the cost threshold: unreliable with an uncertainty of 2.1.
  const Reliability close_cost = decision_reliability(in, uncertainty(0.0, 2.1), 0.1);
  CHECK_FALSE(close_cost.reliable);
  CHECK(mentions(close_cost, "RTR = 100 is 2 decades from 1"));
}

TEST_CASE("a CCM answer is unreliable only when every failing condition is within reach",
          "[recommend]") {
  // u_mean fails by 0.01, u_max by 0.2; RTR > 1 holds.
  const DecisionInputs two_fail = inputs(0.11, 0.3, 0.05, 10.0);
  CHECK(decision_reliability(two_fail, uncertainty(0.05, 0.1), 0.1).reliable);
  CHECK_FALSE(decision_reliability(two_fail, uncertainty(0.25, 0.1), 0.1).reliable);
  // Accurate but CCM is cheaper (RTR 0.8, 0.097 decades below 1): flips only on the cost.
  const DecisionInputs cheap_ccm = inputs(0.01, 0.01, 0.01, 0.8);
  CHECK(decision_reliability(cheap_ccm, uncertainty(1.0, 0.09), 0.1).reliable);
  const Reliability r = decision_reliability(cheap_ccm, uncertainty(0.0, 0.1), 0.1);
  CHECK_FALSE(r.reliable);
  CHECK(mentions(r, "RTR = 0.8"));
  // Both conditions fail, only the error is within reach: the cost still says CCM.
  CHECK(decision_reliability(inputs(0.11, 0.0, 0.0, 0.1), uncertainty(0.05, 0.5), 0.1).reliable);
}
