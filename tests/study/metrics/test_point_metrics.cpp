// All metrics of one grid point from two synthetic runs, against values worked out by hand.
#include <catch2/catch.hpp>

#include "study/metrics/impact_metrics.hpp"
#include "study/metrics/point_metrics.hpp"
#include "tests/study/metrics/synthetic_runs.hpp"
#include "tests/support/tolerance.hpp"

using namespace ccm::study;
using ccm::test::relative_error;
using ccm::test::synthetic_run;

constexpr double kRounding = 1e-14;  // a few flops per figure

TEST_CASE("point metrics of two synthetic runs match the hand computation", "[metrics]") {
  const PointMetrics m =
      compute_point_metrics(synthetic_run(ImpactModel::ccm), synthetic_run(ImpactModel::rigid));
  REQUIRE(m.usable);
  CHECK(m.t_final == 0.15);
  // Cumulative errors as time averages (trapezoids on the uniform samples, docs/metrics.md):
  // u_mean: (c-r)^2 0,0,1,4 -> <.> = 3/3 = 1; <c> 4/3, <r> 2 -> 5/3; 1 / (5/3)      (2.34)
  CHECK(relative_error(m.cumulative.u_mean, 0.6) < kRounding);
  // u_max: (c-r)^2 0,0,1,9 -> 5.5/3; <c> 2.5, <r> 10/3 -> 35/12; 22/35              (2.35)
  CHECK(relative_error(m.cumulative.u_max, 22.0 / 35.0) < kRounding);
  // KE: (c-r)^2 0,0,4,9 -> 8.5/3; <c> 6.5/3, <r> 10/3 -> 2.75; 34/33                (2.36)
  CHECK(relative_error(m.cumulative.kinetic_energy, 34.0 / 33.0) < kRounding);
  // final: |2-4|/4, |3-6|/6, |1-4|/4                          (2.37-2.39)
  CHECK(relative_error(m.final_state.u_mean, 0.5) < kRounding);
  CHECK(relative_error(m.final_state.u_max, 0.5) < kRounding);
  CHECK(relative_error(m.final_state.kinetic_energy, 0.75) < kRounding);
  // Thesis estimate: NT 4e-3/1e-6 = 4000, 1e-3/2e-6 = 500; RTR 8; TR 600 s and 75 s (2.40-2.43)
  CHECK(relative_error(m.ccm.normalised_runtime, 4000.0) < kRounding);
  CHECK(relative_error(m.rigid.normalised_runtime, 500.0) < kRounding);
  CHECK(relative_error(m.ccm.total_runtime_thesis_estimate, 600.0) < kRounding);
  CHECK(relative_error(m.rigid.total_runtime_thesis_estimate, 75.0) < kRounding);
  CHECK(relative_error(m.runtime_ratio_thesis_estimate, 8.0) < kRounding);
  // Measured: the step loops' CPU seconds, 600 s and 300 s (the rigid run took 4 x the steps
  // the estimate assumes); RTR 2
  CHECK(relative_error(m.ccm.total_runtime, 600.0) < kRounding);
  CHECK(relative_error(m.rigid.total_runtime, 300.0) < kRounding);
  CHECK(relative_error(m.runtime_ratio, 2.0) < kRounding);
  // w = final-state error / measured RTR
  CHECK(relative_error(m.weighting.u_mean, 0.25) < kRounding);
  CHECK(relative_error(m.weighting.u_max, 0.25) < kRounding);
  CHECK(relative_error(m.weighting.kinetic_energy, 0.375) < kRounding);
  // Measured timings are carried along.
  CHECK(m.ccm.steps == 150000);
  CHECK(m.rigid.wall_seconds == Approx(300.0).epsilon(1e-14));
}

TEST_CASE("the designer's metrics of two synthetic runs match the hand computation", "[metrics]") {
  const PointMetrics m =
      compute_point_metrics(synthetic_run(ImpactModel::ccm), synthetic_run(ImpactModel::rigid));
  REQUIRE(m.ccm_impact);
  REQUIRE(m.rigid_impact);
  REQUIRE(m.impact_errors);
  // 10 kg, samples 0.05 s apart. CCM: v_z -2, -1, 0.5, 0.5 -> 200 N, 300 N, 0 (IM.1); force in
  // the first two intervals -> 0.1 s (IM.3); u_max peaks at 4 (IM.2); leaves at 0.5 m/s (IM.4).
  CHECK(relative_error(m.ccm_impact->peak_force, 300.0) < kRounding);
  CHECK(relative_error(m.ccm_impact->contact_duration, 0.1) < kRounding);
  CHECK(m.ccm_impact->indentation == 4.0);
  CHECK(relative_error(m.ccm_impact->rebound_speed, 0.5) < kRounding);
  CHECK(m.ccm_impact->approach_speed == 2.0);
  // Rigid: v_z -2, 0, 1, 1 -> 400 N, 200 N, 0; 0.1 s; u_max peaks at 6; leaves at 1 m/s.
  CHECK(relative_error(m.rigid_impact->peak_force, 400.0) < kRounding);
  CHECK(relative_error(m.rigid_impact->contact_duration, 0.1) < kRounding);
  CHECK(m.rigid_impact->indentation == 6.0);
  CHECK(relative_error(m.rigid_impact->rebound_speed, 1.0) < kRounding);
  // IM.5: 100 / 400, 2 / 6, 0, 0.5 / 2.
  CHECK(relative_error(m.impact_errors->peak_force, 0.25) < kRounding);
  CHECK(relative_error(m.impact_errors->indentation, 1.0 / 3.0) < kRounding);
  CHECK(m.impact_errors->contact_duration == 0.0);
  CHECK(relative_error(m.impact_errors->rebound_speed, 0.25) < kRounding);
  CHECK(relative_error(m.impact_errors->worst(), 1.0 / 3.0) < kRounding);
}

TEST_CASE("the designer's metrics: an oblique blow, a noise floor, a run without the history",
          "[metrics]") {
  RunRecord run = synthetic_run(ImpactModel::ccm);
  // Along x as well: 10 kg x |(0.3, 0, 0.4)| / 0.05 s = 100 N in the first interval; then a
  // change below 1e-3 of the peak in the last (noise, not contact).
  run.impactor.vx = {0.3, 0.0, 0.0, 0.0};
  run.impactor.vz = {-0.4, 0.0, 0.0, 1e-7};
  const auto q = ccm::study::impact_quantities(run);
  REQUIRE(q);
  CHECK(relative_error(q->peak_force, 100.0) < kRounding);
  CHECK(relative_error(q->approach_speed, 0.5) < kRounding);
  CHECK(relative_error(q->contact_duration, 0.05) < kRounding);
  // Leaving at 1e-7 m/s along +z: -v . e = 1e-7 x 0.8.
  CHECK(relative_error(q->rebound_speed, 0.8e-7) < 1e-9);
  run.impactor = {};
  CHECK_FALSE(ccm::study::impact_quantities(run));
  const PointMetrics m = compute_point_metrics(run, synthetic_run(ImpactModel::rigid));
  CHECK(m.usable);  // the thesis's metrics do not need it
  CHECK_FALSE(m.impact_errors);
}

TEST_CASE("a point with an unstable run is kept but marked unusable, with the reason",
          "[metrics]") {
  RunRecord ccm_run = synthetic_run(ImpactModel::ccm);
  ccm_run.verdict = "unstable";
  ccm_run.reason = "energy balance error 27.7 % exceeds 5 %";
  const PointMetrics m = compute_point_metrics(ccm_run, synthetic_run(ImpactModel::rigid));
  CHECK_FALSE(m.usable);
  CHECK(m.excluded_reason == "ccm run unstable: energy balance error 27.7 % exceeds 5 %");
  CHECK(m.ccm.verdict == "unstable");
  CHECK(m.rigid.verdict == "completed");
}

TEST_CASE("runs sampled at different times are not compared", "[metrics]") {
  RunRecord rigid = synthetic_run(ImpactModel::rigid);
  rigid.artifact.time[2] = 0.11;
  const PointMetrics m = compute_point_metrics(synthetic_run(ImpactModel::ccm), rigid);
  CHECK_FALSE(m.usable);
  CHECK(m.excluded_reason == "sample 2 is at different times in the two runs");
  // Swapped models or different points are a programming error.
  CHECK_THROWS(
      compute_point_metrics(synthetic_run(ImpactModel::rigid), synthetic_run(ImpactModel::ccm)));
  CHECK_THROWS(compute_point_metrics(synthetic_run(ImpactModel::ccm, 1),
                                     synthetic_run(ImpactModel::rigid, 2)));
}

TEST_CASE(
    "a point whose run has no measured cost (an old store's row) is unusable, with the reason",
    "[metrics]") {
  RunRecord rigid_run = synthetic_run(ImpactModel::rigid);
  rigid_run.cost.reset();
  const PointMetrics m = compute_point_metrics(synthetic_run(ImpactModel::ccm), rigid_run);
  CHECK_FALSE(m.usable);
  CHECK(m.excluded_reason.find("rigid run: its cost was not measured") != std::string::npos);
  CHECK(m.runtime_ratio == 0.0);
}
