#include "study/recommend/decision_rule.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace ccm::study {
namespace {

struct NamedError {
  const char* name;
  double value, uncertainty;
};

std::array<NamedError, 3> named_errors(const DecisionInputs& in, const DecisionUncertainty& u) {
  return {NamedError{"u_mean", in.final_state.u_mean, u.final_state.u_mean},
          NamedError{"u_max", in.final_state.u_max, u.final_state.u_max},
          NamedError{"KE", in.final_state.kinetic_energy, u.final_state.kinetic_energy}};
}

std::string error_margin(const NamedError& e, double max_error) {
  return fmt::format(
      "final-state error {} = {:.3g} is {:.3g} from the threshold {:g}, within its leave-one-out "
      "error {:.3g}",
      e.name, e.value, std::abs(e.value - max_error), max_error, e.uncertainty);
}

std::string cost_margin(double runtime_ratio, double uncertainty) {
  return fmt::format(
      "RTR = {:.3g} is {:.3g} decades from 1 (the cost threshold), within its leave-one-out error "
      "{:.3g} decades",
      runtime_ratio, std::abs(std::log10(runtime_ratio)), uncertainty);
}

}  // namespace

Decision decide_model(const DecisionInputs& in, double max_error) {
  const ArtifactErrors& e = in.final_state;
  const std::array<double, 3> errors = {e.u_mean, e.u_max, e.kinetic_energy};
  return decide_model(errors, in.runtime_ratio, max_error);
}

Decision decide_model(std::span<const double> final_state_errors, double runtime_ratio,
                      double max_error) {
  Decision d;
  for (double e : final_state_errors) d.worst_error = std::max(d.worst_error, e);
  d.rigid_within_error = d.worst_error <= max_error;
  d.rigid_cheaper = runtime_ratio > 1.0;
  d.model = d.rigid_within_error && d.rigid_cheaper ? ImpactModel::rigid : ImpactModel::ccm;
  return d;
}

Reliability decision_reliability(const DecisionInputs& in, const DecisionUncertainty& u,
                                 double max_error) {
  const Decision d = decide_model(in, max_error);
  const double log_rtr = std::log10(in.runtime_ratio);
  const bool cost_close = std::abs(log_rtr) <= u.log10_runtime_ratio;
  Reliability r;
  if (d.model == ImpactModel::rigid) {  // flips when any one condition can fail
    for (const NamedError& e : named_errors(in, u))
      if (max_error - e.value <= e.uncertainty) r.reasons.push_back(error_margin(e, max_error));
    if (cost_close) r.reasons.push_back(cost_margin(in.runtime_ratio, u.log10_runtime_ratio));
    r.reliable = r.reasons.empty();
    return r;
  }
  // CCM flips only when every failing condition can hold.
  bool all_failing_close = true;
  for (const NamedError& e : named_errors(in, u))
    if (e.value > max_error) {
      if (e.value - max_error <= e.uncertainty)
        r.reasons.push_back(error_margin(e, max_error));
      else
        all_failing_close = false;
    }
  if (!d.rigid_cheaper) {
    if (cost_close)
      r.reasons.push_back(cost_margin(in.runtime_ratio, u.log10_runtime_ratio));
    else
      all_failing_close = false;
  }
  r.reliable = !all_failing_close;
  if (r.reliable) r.reasons.clear();
  return r;
}

std::string decision_rule_text(double max_error) {
  return fmt::format(
      "rule: use the rigid model where its final-state error against CCM is within {:g} on every "
      "metric (u_mean, u_max, KE) AND it is cheaper (RTR = TR_ccm / TR_rigid > 1); otherwise CCM",
      max_error);
}

std::string decision_reason(const DecisionInputs& in, const Decision& d, double max_error) {
  const ArtifactErrors& e = in.final_state;
  const std::string errors =
      fmt::format("u_mean {:.3g}, u_max {:.3g}, KE {:.3g}", e.u_mean, e.u_max, e.kinetic_energy);
  const std::string cost =
      d.rigid_cheaper
          ? fmt::format("CCM costs {:.3g}x the rigid model (RTR > 1)", in.runtime_ratio)
          : fmt::format("CCM costs {:.3g}x the rigid model: it is not dearer (RTR <= 1)",
                        in.runtime_ratio);
  return fmt::format("{}: final-state errors of the rigid model ({}) are {} {:g}; {}",
                     to_string(d.model), errors,
                     d.rigid_within_error ? "all within" : "not all within", max_error, cost);
}

}  // namespace ccm::study
