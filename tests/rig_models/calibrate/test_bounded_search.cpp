// The calibration's search (rig_models/calibrate/bounded_search.hpp) on objectives with known
// minima: it finds them inside the bounds, stops at a bound when the minimum lies beyond it,
// starts at the given point, steers around failed evaluations and is deterministic.
#include <catch2/catch.hpp>
#include <cmath>

#include "rig_models/calibrate/bounded_search.hpp"
#include "rig_models/calibrate/rig_objective.hpp"

using namespace ccm::rig;

namespace {

// A friction-like pair of unequal scales: minimum at mu_s = 0.3, mu_k = 0.12.
std::optional<double> bowl(const std::vector<double>& x) {
  return std::pow((x[0] - 0.3) / 0.1, 2) + std::pow((x[1] - 0.12) / 0.05, 2) + 0.25;
}

}  // namespace

TEST_CASE("bounded search: finds a minimum inside the bounds in few evaluations",
          "[rig][calibrate]") {
  const std::vector<SearchParameter> p{{"mu_s", 0.0, 1.0, 0.2}, {"mu_k", 0.0, 1.0, 0.1}};
  const SearchResult r = bounded_search(p, bowl, {40, 1e-6});
  CHECK(r.algorithm == "LN_BOBYQA");
  REQUIRE(!r.history.empty());
  CHECK(r.history.front().x == std::vector<double>{0.2, 0.1});  // starts where it is told
  CHECK(r.history.size() <= 40);
  // A quadratic is BOBYQA's own model: it lands on the minimum to the x tolerance.
  CHECK(r.best[0] == Approx(0.3).margin(1e-3));
  CHECK(r.best[1] == Approx(0.12).margin(1e-3));
  CHECK(r.best_objective == Approx(0.25).margin(1e-4));
  for (const SearchEvaluation& e : r.history)
    for (size_t i = 0; i < 2; ++i) CHECK((e.x[i] >= 0.0 && e.x[i] <= 1.0));
  // Deterministic: the same sequence again.
  const SearchResult again = bounded_search(p, bowl, {40, 1e-6});
  REQUIRE(again.history.size() == r.history.size());
  for (size_t k = 0; k < r.history.size(); ++k) CHECK(again.history[k].x == r.history[k].x);
}

TEST_CASE("bounded search: one parameter (COBYLA), a minimum beyond the bound, failures",
          "[rig][calibrate]") {
  const std::vector<SearchParameter> p{{"spring_stiffness", 1000.0, 3000.0, 1895.0}};
  // Minimum at 4000 N/m, beyond the upper bound: the search ends on the bound.
  const auto beyond = [](const std::vector<double>& x) -> std::optional<double> {
    return std::pow(x[0] - 4000.0, 2);
  };
  const SearchResult r = bounded_search(p, beyond, {30, 1e-6});
  CHECK(r.algorithm == "LN_COBYLA");
  CHECK(r.best[0] == Approx(3000.0).margin(1.0));
  // Evaluations that fail (unstable runs) are steered around: the minimum at 1500 is found
  // although everything above 2500 fails.
  const auto fragile = [](const std::vector<double>& x) -> std::optional<double> {
    if (x[0] > 2500.0) return std::nullopt;
    return std::pow((x[0] - 1500.0) / 100.0, 2);
  };
  const SearchResult f = bounded_search(p, fragile, {30, 1e-6});
  CHECK(f.best[0] == Approx(1500.0).margin(5.0));
  CHECK(f.best_objective < 0.01);
}

TEST_CASE("bounded search: bad ranges and starts are refused", "[rig][calibrate]") {
  CHECK_THROWS_WITH(bounded_search({{"mu_s", 1.0, 1.0, 1.0}}, bowl, {}),
                    "calibration: mu_s: the range [1, 1] is empty");
  CHECK_THROWS_WITH(bounded_search({{"mu_s", 0.0, 1.0, 2.0}}, bowl, {}),
                    "calibration: mu_s: the starting value 2 lies outside [0, 1]");
  CHECK_THROWS_WITH(bounded_search({}, bowl, {}), "calibration: no parameter to tune");
}

TEST_CASE("calibration objective: the mean over channels of the trials' mean nRMSE",
          "[rig][calibrate]") {
  CaseComparison c;
  auto channel = [](std::vector<std::optional<double>> nrmse) {
    ChannelAgainstTrials a;
    for (auto v : nrmse) {
      ChannelComparison cc;
      cc.nrmse = v;
      a.per_trial.push_back(cc);
    }
    return a;
  };
  c.velocity = channel({0.1, 0.3});        // mean 0.2
  c.angle = channel({0.4, std::nullopt});  // 0.4 (the constant trial left out)
  c.pressure = channel({0.6, 0.6});        // 0.6
  CHECK(calibration_objective(c).value() == Approx((0.2 + 0.4 + 0.6) / 3.0));
  c.velocity = c.angle = c.pressure = channel({std::nullopt});
  CHECK(!calibration_objective(c));
}

TEST_CASE("calibration objective over some trials: those trials' nRMSE alone", "[rig][calibrate]") {
  // Trials 1 and 3 (trial 2 drove the run): per channel, trial 1's and trial 3's nRMSE.
  CaseComparison c;
  c.trials = {1, 3};
  auto channel = [](std::optional<double> first, std::optional<double> second) {
    ChannelAgainstTrials a;
    for (auto v : {first, second}) {
      ChannelComparison cc;
      cc.nrmse = v;
      a.per_trial.push_back(cc);
    }
    return a;
  };
  c.velocity = channel(0.1, 0.3);
  c.angle = channel(0.4, std::nullopt);  // trial 3's angle constant: no nRMSE
  c.pressure = channel(0.6, 0.9);
  CHECK(calibration_objective(c, {1}).value() == Approx((0.1 + 0.4 + 0.6) / 3.0));
  CHECK(calibration_objective(c, {3}).value() == Approx((0.3 + 0.9) / 2.0));
  CHECK(calibration_objective(c, {1, 3}).value() == Approx(calibration_objective(c).value()));
  CHECK(!calibration_objective(c, {2}));  // not a trial of the comparison
}
