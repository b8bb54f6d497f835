// The calibration's search (rig_models/calibrate/bounded_search.hpp) on objectives with known
// minima: it finds them inside the bounds, stops at a bound when the minimum lies beyond it,
// starts at the given point, steers around failed evaluations and is deterministic; its opening
// points go out as one batch, every one of them used, none evaluated twice, within the budget.
#include <algorithm>
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

// A bowl in any number of parameters, minimum inside [0, 1] at 0.3, 0.12, 0.6, ...
std::optional<double> bowl_n(const std::vector<double>& x) {
  double f = 0.25;
  for (size_t i = 0; i < x.size(); ++i) f += std::pow((x[i] - 0.3 + 0.1 * double(i % 3)) / 0.1, 2);
  return f;
}

struct Batches {
  std::vector<size_t> sizes;
  BatchObjective objective() {
    return [this](const std::vector<std::vector<double>>& points) {
      sizes.push_back(points.size());
      return one_at_a_time(bowl_n)(points);
    };
  }
};

TEST_CASE("bounded search: the opening points go out as one batch and every one is used",
          "[rig][calibrate]") {
  // Starts in the middle (BOBYQA's own start), near a bound (moved off it before its design),
  // on a bound, in two and three parameters (BOBYQA) and one (COBYLA).
  const std::vector<std::vector<double>> starts{
      {0.5, 0.5},      {0.2, 0.1}, {0.0, 1.0}, {0.9, 0.05}, {0.5, 0.4, 0.3},
      {0.0, 0.7, 1.0}, {0.5},      {0.1},      {1.0},       {0.95}};
  for (const std::vector<double>& start : starts) {
    std::vector<SearchParameter> p;
    for (size_t i = 0; i < start.size(); ++i)
      p.push_back({"p" + std::to_string(i), 0.0, 1.0, start[i]});
    const size_t n = start.size();
    const size_t opening = n >= 2 ? 2 * n + 1 : n + 1;
    for (int budget : {1, 3, 12, 30}) {
      INFO("start " << start[0] << " ... of " << n << ", budget " << budget);
      Batches batches;
      const SearchResult r = bounded_search(p, batches.objective(), {budget, 1e-6});
      CHECK(r.unused_evaluations == 0);
      CHECK(r.history.front().x == start);
      CHECK(static_cast<int>(r.history.size()) <= budget);
      if (r.stop_reason == "MAXEVAL_REACHED") CHECK(static_cast<int>(r.history.size()) == budget);
      // The first batch is the start and the opening points within the budget (less the start
      // when it is one of them).
      REQUIRE(!batches.sizes.empty());
      const size_t opened = std::min(opening, static_cast<size_t>(budget - 1));
      CHECK(batches.sizes.front() >= std::max<size_t>(opened, 1));
      CHECK(batches.sizes.front() <= opened + 1);
      for (size_t k = 1; k < batches.sizes.size(); ++k) CHECK(batches.sizes[k] == 1);
      // No point evaluated twice.
      for (size_t a = 0; a < r.history.size(); ++a)
        for (size_t b = a + 1; b < r.history.size(); ++b) CHECK(r.history[a].x != r.history[b].x);
    }
  }
}

TEST_CASE("bounded search: the same evaluations batched or one at a time", "[rig][calibrate]") {
  const std::vector<SearchParameter> p{{"mu_s", 0.0, 1.0, 0.5}, {"mu_k", 0.0, 1.0, 0.5}};
  Batches batches;
  const SearchResult batched = bounded_search(p, batches.objective(), {20, 1e-6});
  const SearchResult single = bounded_search(p, bowl_n, {20, 1e-6});
  REQUIRE(batched.history.size() == single.history.size());
  for (size_t k = 0; k < single.history.size(); ++k) {
    CHECK(batched.history[k].x == single.history[k].x);
    CHECK(batched.history[k].objective == single.history[k].objective);
  }
  CHECK(batched.best == single.best);
  // From the middle BOBYQA starts where the caller does: the start is one of its 5 opening
  // points, read back rather than run again, so the first batch holds 5 points, not 6.
  CHECK(batches.sizes.front() == 5);
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
