// A rig case's comparison (rig::CaseComparison) as rows "case,item,trial,field,value", and the
// simulated curves the rig-comparison equality test scores: the fixture of
// tests/data/rig-comparison-before-bench-path.csv was written by these from the rig's own
// comparison before it went through the bench test's scoring.
#pragma once

#include <fmt/format.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "rig_models/compare/case_comparison.hpp"
#include "rig_models/signal/resample.hpp"

namespace ccm::test {

inline void add_channel_rows(std::vector<std::string>& rows, const std::string& code,
                             const std::string& item, int trial, const rig::ChannelComparison& c) {
  auto add = [&](const char* field, double v) {
    rows.push_back(fmt::format("{},{},{},{},{:.17g}", code, item, trial, field, v));
  };
  add("n_samples", static_cast<double>(c.n_samples));
  add("rmse", c.rmse);
  if (c.nrmse) add("nrmse", *c.nrmse);
  add("peak_measured", c.peak_measured);
  add("peak_simulated", c.peak_simulated);
  add("peak_error", c.peak_error);
  add("peak_time_error", c.peak_time_error);
}

inline void add_window_rows(std::vector<std::string>& rows, const std::string& code,
                            const std::string& item, int trial,
                            const std::optional<rig::ContactWindow>& w) {
  if (!w) return;
  rows.push_back(fmt::format("{},{},{},onset,{:.17g}", code, item, trial, w->onset));
  rows.push_back(fmt::format("{},{},{},duration,{:.17g}", code, item, trial, w->duration));
  rows.push_back(fmt::format("{},{},{},released,{}", code, item, trial, w->released ? 1 : 0));
}

inline std::vector<std::string> comparison_rows(const std::string& code,
                                                const rig::CaseComparison& c) {
  std::vector<std::string> rows;
  for (std::size_t i = 0; i < c.trials.size(); ++i) {
    const int trial = c.trials[i];
    add_channel_rows(rows, code, "velocity", trial, c.velocity.per_trial[i]);
    add_channel_rows(rows, code, "angle", trial, c.angle.per_trial[i]);
    add_channel_rows(rows, code, "pressure", trial, c.pressure.per_trial[i]);
    if (c.velocity_in_contact.per_trial[i])
      add_channel_rows(rows, code, "velocity_in_contact", trial,
                       *c.velocity_in_contact.per_trial[i]);
    add_window_rows(rows, code, "contact_measured", trial, c.contact[i].measured);
    add_window_rows(rows, code, "contact_simulated", trial, c.contact[i].simulated);
  }
  auto spread = [&](const std::string& item, const std::optional<rig::Spread>& s) {
    if (!s) return;
    for (const auto& [field, v] : {std::pair{"mean", s->mean}, std::pair{"std_dev", s->std_dev},
                                   std::pair{"min", s->min}, std::pair{"max", s->max}})
      rows.push_back(fmt::format("{},{},0,{},{:.17g}", code, item, field, v));
  };
  spread("velocity.rmse", c.velocity.rmse);
  spread("velocity.peak_error", c.velocity.peak_error);
  spread("velocity.peak_time_error", c.velocity.peak_time_error);
  spread("angle.rmse", c.angle.rmse);
  spread("pressure.rmse", c.pressure.rmse);
  spread("pressure.peak_error", c.pressure.peak_error);
  spread("velocity_in_contact.rmse", c.velocity_in_contact.rmse);
  spread("velocity_in_contact.nrmse", c.velocity_in_contact.nrmse);
  spread("onset_error", c.onset_error);
  spread("duration_error", c.duration_error);
  return rows;
}

// The simulated curves of a case, made from its trial 2 (the default driving trial): on a
// uniform 1 ms clock over that trial's span less 10 ms at the end, delayed by 4 ms, V_i times
// 1.05 plus 0.01 m/s, theta_a times 0.8, the raw pressure times 1.3 (before the sensor model).
struct RawCurves {
  rig::TimeSeries velocity_mps, angle_deg, pressure_raw_kpa;
};

inline rig::TimeSeries delayed_scaled(const rig::TimeSeries& s, double t0, double t1, double gain,
                                      double offset) {
  rig::TimeSeries out;
  constexpr double kDelay = 0.004, kStep = 0.001;
  for (int k = 0;; ++k) {
    const double t = t0 + k * kStep;
    if (t > t1) break;
    const double source = std::max(s.t.front(), std::min(s.t.back(), t - kDelay));
    const double v = rig::sample_at(s, std::vector<double>{source}).value[0];
    out.t.push_back(t);
    out.value.push_back(gain * v + offset);
  }
  return out;
}

inline RawCurves raw_curves_from(const rig::MeasuredTrial& m) {
  const double t0 = std::max({m.impactor_velocity_mps.t.front(), m.artifact_angle_deg.t.front(),
                              m.pressure_kpa.t.front()});
  const double t1 = std::min({m.impactor_velocity_mps.t.back(), m.artifact_angle_deg.t.back(),
                              m.pressure_kpa.t.back()}) -
                    0.010;
  return {delayed_scaled(m.impactor_velocity_mps, t0, t1, 1.05, 0.01),
          delayed_scaled(m.artifact_angle_deg, t0, t1, 0.8, 0.0),
          delayed_scaled(m.pressure_kpa, t0, t1, 1.3, 0.0)};
}

}  // namespace ccm::test
