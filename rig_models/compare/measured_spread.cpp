#include "rig_models/compare/measured_spread.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rig_models/compare/channel_metrics.hpp"

namespace ccm::rig {
namespace {

double peak_of(const TimeSeries& s) {
  const auto it = std::max_element(s.value.begin(), s.value.end(),
                                   [](double a, double b) { return std::abs(a) < std::abs(b); });
  return *it;
}

ChannelSpread channel_spread(std::span<const MeasuredTrial> trials,
                             TimeSeries MeasuredTrial::*member) {
  std::vector<TimeSeries> series;
  std::vector<double> peaks;
  for (const MeasuredTrial& m : trials) {
    series.push_back(m.*member);
    peaks.push_back(peak_of(m.*member));
  }
  ChannelSpread c;
  c.peak = spread_of(peaks);
  if (series.size() >= 2) {
    const ChannelEnsemble e = channel_ensemble(series);
    double sum = 0.0;
    for (double s : e.spread) sum += s * s;
    c.spread_rms = std::sqrt(sum / static_cast<double>(e.spread.size()));
  }
  return c;
}

}  // namespace

MeasuredSpread measured_spread(std::span<const MeasuredTrial> trials, double contact_threshold) {
  if (trials.empty()) throw std::invalid_argument("measured spread: no trial");
  MeasuredSpread out;
  out.n_trials = static_cast<int>(trials.size());
  out.velocity = channel_spread(trials, &MeasuredTrial::impactor_velocity_mps);
  out.angle = channel_spread(trials, &MeasuredTrial::artifact_angle_deg);
  out.pressure = channel_spread(trials, &MeasuredTrial::pressure_kpa);
  std::vector<double> onset, duration;
  for (const MeasuredTrial& m : trials)
    if (const auto w = first_contact(m.pressure_kpa, contact_threshold)) {
      onset.push_back(w->onset);
      duration.push_back(w->duration);
    }
  if (!onset.empty()) {
    out.onset = spread_of(onset);
    out.duration = spread_of(duration);
  }
  return out;
}

}  // namespace ccm::rig
