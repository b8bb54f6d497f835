// Mean and spread over trials, and a simulation against each trial, on hand-computed values.
#include <catch2/catch.hpp>
#include <cmath>
#include <stdexcept>

#include "rig_models/compare/trial_ensemble.hpp"
#include "tests/support/tolerance.hpp"

using namespace ccm::rig;
using ccm::test::relative_error;

TEST_CASE("trial ensemble: pointwise mean and sample standard deviation", "[rig]") {
  const std::vector<TimeSeries> trials = {{{0.0, 1.0, 2.0}, {1.0, 2.0, 3.0}},
                                          {{0.0, 1.0, 2.0}, {2.0, 3.0, 4.0}},
                                          {{0.0, 1.0, 2.0}, {3.0, 4.0, 8.0}}};
  const ChannelEnsemble e = channel_ensemble(trials);
  CHECK(e.mean.t == std::vector<double>{0.0, 1.0, 2.0});
  CHECK(e.mean.value == std::vector<double>{2.0, 3.0, 5.0});
  // (1-2)^2 + 0 + (3-2)^2 = 2 over n - 1 = 2: 1; at t = 2: (4 + 1 + 9) / 2 = 7
  CHECK(e.spread[0] == 1.0);
  CHECK(e.spread[1] == 1.0);
  CHECK(relative_error(e.spread[2], std::sqrt(7.0)) < 1e-15);
}

TEST_CASE("trial ensemble: trials on other timestamps are interpolated on the first's", "[rig]") {
  // the second trial covers [0.5, 2.5] only: the common times are 1 and 2; it reads 1.5 and 2.5
  const std::vector<TimeSeries> trials = {{{0.0, 1.0, 2.0, 3.0}, {0.0, 1.0, 2.0, 3.0}},
                                          {{0.5, 1.5, 2.5}, {1.0, 2.0, 3.0}}};
  const ChannelEnsemble e = channel_ensemble(trials);
  CHECK(e.mean.t == std::vector<double>{1.0, 2.0});
  CHECK(e.mean.value == std::vector<double>{1.25, 2.25});
  CHECK(relative_error(e.spread[0], std::sqrt(0.125)) < 1e-15);  // (0.25^2 * 2) / 1
  CHECK_THROWS_WITH(channel_ensemble(std::span(trials).first(1)),
                    "trial ensemble: 1 trial(s), at least 2 needed");
}

TEST_CASE("spread of values: mean, sample standard deviation, min, max", "[rig]") {
  const std::vector<double> v = {1.0, 2.0, 3.0, 4.0};
  const Spread s = spread_of(v);
  CHECK(s.mean == 2.5);
  CHECK(relative_error(s.std_dev, std::sqrt(5.0 / 3.0)) < 1e-15);
  CHECK(s.min == 1.0);
  CHECK(s.max == 4.0);
  CHECK(spread_of(std::vector<double>{7.0}).std_dev == 0.0);
}

TEST_CASE("simulation against each trial: per-trial metrics and their spread", "[rig]") {
  const std::vector<TimeSeries> trials = {{{0.0, 1.0, 2.0}, {1.0, 2.0, 3.0}},
                                          {{0.0, 1.0, 2.0}, {2.0, 3.0, 4.0}},
                                          {{0.0, 1.0, 2.0}, {3.0, 4.0, 5.0}}};
  const TimeSeries simulated{{0.0, 2.0}, {2.0, 4.0}};  // 2, 3, 4 on the trials' times
  const ChannelAgainstTrials c = compare_with_trials(trials, simulated);
  REQUIRE(c.per_trial.size() == 3);
  // RMSE 1, 0, 1: mean 2/3, standard deviation sqrt(((1/3)^2 * 2 + (2/3)^2) / 2) = sqrt(1/3)
  CHECK(relative_error(c.rmse.mean, 2.0 / 3.0) < 1e-15);
  CHECK(relative_error(c.rmse.std_dev, std::sqrt(1.0 / 3.0)) < 1e-15);
  // peaks (largest |value|, all at t = 2): 4 - 3, 4 - 4, 4 - 5
  CHECK(c.peak_error.mean == 0.0);
  CHECK(c.peak_error.min == -1.0);
  CHECK(c.peak_error.max == 1.0);
  CHECK(c.peak_time_error.max == 0.0);
}
