#include "bench_test/bench_scores.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "config/config_error.hpp"
#include "correlate/cfc_filter.hpp"
#include "rig_models/compare/channel_metrics.hpp"
#include "rig_models/signal/low_pass.hpp"
#include "rig_models/signal/resample.hpp"

namespace ccm::bench {

namespace {

constexpr std::size_t kMinScoredSamples = 10;  // what a rating needs

double median_step(const std::vector<double>& t) {
  std::vector<double> d;
  for (std::size_t k = 1; k < t.size(); ++k) d.push_back(t[k] - t[k - 1]);
  std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
  return d[d.size() / 2];
}

// The times t0, t0 + step, ... up to t1.
std::vector<double> uniform_times(double t0, double t1, double step) {
  std::vector<double> t;
  const auto n = static_cast<std::size_t>(std::floor((t1 - t0) / step * (1.0 + 1e-12))) + 1;
  // (the last one clamped: t0 + n step may round past t1 by an ulp)
  for (std::size_t k = 0; k < n; ++k) t.push_back(std::min(t1, t0 + static_cast<double>(k) * step));
  return t;
}

// The filter and the deadband of the channel, on a uniformly sampled curve.
rig::TimeSeries conditioned(rig::TimeSeries s, double step, const ChannelSpec& c) {
  if (c.filter.kind == FilterKind::cfc)
    s.value = correlate::cfc_filter(s.value, c.filter.frequency, step);
  else if (c.filter.kind == FilterKind::low_pass)
    s = rig::apply_low_pass(s, c.filter.frequency);
  if (c.deadband > 0.0)
    for (double& v : s.value)
      if (std::abs(v) < c.deadband) v = 0.0;
  return s;
}

// A curve on a uniform clock of `step` over its own span, then conditioned.
rig::TimeSeries uniform_conditioned(const rig::TimeSeries& s, double step, const ChannelSpec& c) {
  return conditioned(rig::sample_at(s, uniform_times(s.t.front(), s.t.back(), step)), step, c);
}

// The simulated curve conditioned for comparison with samples every `measured_step`: where the
// simulation writes more often than the logger samples, it is filtered at its own rate first
// (sampling the unfiltered curve at the logger's instants would alias what lies above the
// logger's Nyquist frequency, as a logger's anti-aliasing filter does not let it); otherwise it
// is interpolated onto the logger's rate and filtered there.
rig::TimeSeries simulated_conditioned(const rig::TimeSeries& s, double measured_step,
                                      const ChannelSpec& c) {
  const double own_step = median_step(s.t);
  if (own_step < measured_step && c.filter.kind != FilterKind::none)
    return uniform_conditioned(s, own_step, c);
  return uniform_conditioned(s, measured_step, c);
}

// The time |value| first reaches `threshold`, interpolated between the samples around it.
std::optional<double> trigger_time(const rig::TimeSeries& s, double threshold) {
  for (std::size_t k = 0; k < s.t.size(); ++k) {
    const double a = std::abs(s.value[k]);
    if (a < threshold) continue;
    if (k == 0) return s.t[0];
    const double b = std::abs(s.value[k - 1]);
    return s.t[k - 1] + (threshold - b) / (a - b) * (s.t[k] - s.t[k - 1]);
  }
  return std::nullopt;
}

rig::TimeSeries shifted(rig::TimeSeries s, double shift) {
  for (double& t : s.t) t += shift;
  return s;
}

// The samples of `s` with t in [t0, t1].
rig::TimeSeries within(const rig::TimeSeries& s, double t0, double t1) {
  rig::TimeSeries out;
  for (std::size_t k = 0; k < s.t.size(); ++k)
    if (s.t[k] >= t0 && s.t[k] <= t1) {
      out.t.push_back(s.t[k]);
      out.value.push_back(s.value[k]);
    }
  return out;
}

ChannelScore score(std::string against, const rig::TimeSeries& measured,
                   const rig::TimeSeries& simulated, double step) {
  const rig::ChannelComparison c = rig::compare_channel(measured, simulated);
  ChannelScore s;
  s.against = std::move(against);
  s.samples = c.n_samples;
  s.nrmse = c.nrmse;
  s.peak_measured = c.peak_measured;
  s.peak_simulated = c.peak_simulated;
  s.peak_error = c.peak_error;
  s.peak_time_error = c.peak_time_error;
  s.rating = correlate::iso18571_rating(measured.value, simulated.value, step);
  return s;
}

struct Window {
  double t0, t1;
};

// The channel's window inside the span of the conditioned simulated curve.
Window window_of(const ChannelSpec& c, const rig::TimeSeries& sim) {
  Window w{sim.t.front(), sim.t.back()};
  if (c.window) w = {std::max(w.t0, (*c.window)[0]), std::min(w.t1, (*c.window)[1])};
  return w;
}

}  // namespace

std::vector<PreparedTrial> prepare_trials(const BenchMapping& m,
                                          const std::vector<BenchTrial>& trials) {
  std::vector<PreparedTrial> out;
  for (const BenchTrial& trial : trials) {
    PreparedTrial p;
    p.name = trial.file.filename().string();
    for (const ChannelSpec& c : m.channels) {
      const rig::TimeSeries& raw = trial.channels.at(c.name);
      const double step = p.steps[c.name] = median_step(raw.t);
      try {
        p.channels[c.name] =
            c.condition_measured
                ? uniform_conditioned(raw, step, c)
                : rig::sample_at(raw, uniform_times(raw.t.front(), raw.t.back(), step));
      } catch (const std::invalid_argument& e) {
        throw config_error(
            m.file, c.line, fmt::format("channels.{}.filter", c.name),
            fmt::format("on {} (samples every {:.6g} s): {}", p.name, step, e.what()));
      }
    }
    if (m.align.channel) {
      p.trigger_time = trigger_time(p.channels.at(*m.align.channel), m.align.threshold);
      if (!p.trigger_time)
        throw config_error(m.file, m.align.line, "align.threshold",
                           fmt::format("{}: channel '{}' never reaches {:g} (its largest |value| "
                                       "is {:.6g}, SI units, filtered)",
                                       p.name, *m.align.channel, m.align.threshold, [&] {
                                         double mx = 0;
                                         for (double v : p.channels.at(*m.align.channel).value)
                                           mx = std::max(mx, std::abs(v));
                                         return mx;
                                       }()));
    }
    out.push_back(std::move(p));
  }
  return out;
}

BenchScores score_bench_test(const BenchMapping& m, const std::vector<PreparedTrial>& trials,
                             const std::map<std::string, rig::TimeSeries>& simulated) {
  BenchScores out;
  // The clocks: each trial's shift onto the simulation's.
  std::optional<double> sim_trigger;
  if (m.align.channel) {
    const ChannelSpec& c = *m.channel(*m.align.channel);
    sim_trigger =
        trigger_time(simulated_conditioned(simulated.at(c.name), trials[0].steps.at(c.name), c),
                     m.align.threshold);
    if (!sim_trigger)
      throw ScoringError(fmt::format(
          "the simulated '{}' never reaches the trigger threshold {:g}: the trials' clocks cannot "
          "be aligned with it (align.threshold in {})",
          c.name, m.align.threshold, m.file.string()));
  }
  for (std::size_t i = 0; i < trials.size(); ++i)
    out.clock_shifts.push_back(sim_trigger               ? *sim_trigger - *trials[i].trigger_time
                               : m.align.offsets.empty() ? 0.0
                                                         : m.align.offsets[i]);
  for (const ChannelSpec& c : m.channels) {
    // Conditioned for the first trial's rate; a trial at another rate gets its own below.
    const double step0 = trials[0].steps.at(c.name);
    const rig::TimeSeries sim = simulated_conditioned(simulated.at(c.name), step0, c);
    const Window w = window_of(c, sim);
    ChannelResult result;
    result.channel = c.name;
    std::vector<rig::TimeSeries> aligned;
    for (std::size_t i = 0; i < trials.size(); ++i) {
      const PreparedTrial& trial = trials[i];
      const rig::TimeSeries sim_u =
          trial.steps.at(c.name) == step0
              ? sim
              : simulated_conditioned(simulated.at(c.name), trial.steps.at(c.name), c);
      const rig::TimeSeries measured =
          within(shifted(trial.channels.at(c.name), out.clock_shifts[i]),
                 std::max(w.t0, sim_u.t.front()), std::min(w.t1, sim_u.t.back()));
      if (measured.t.size() < kMinScoredSamples)
        throw ScoringError(fmt::format(
            "channel '{}': {} holds {} samples inside the simulated span and the window [{:.6g}, "
            "{:.6g}] s; a score needs {}",
            c.name, trial.name, measured.t.size(), w.t0, w.t1, kMinScoredSamples));
      result.trials.push_back(
          score(trial.name, measured, rig::sample_at(sim_u, measured.t), trial.steps.at(c.name)));
      aligned.push_back(shifted(trial.channels.at(c.name), out.clock_shifts[i]));
    }
    // The mean of the trials on the first one's samples where every trial has samples.
    if (aligned.empty()) throw std::logic_error("a bench test has at least one trial");
    rig::TimeSeries first = within(aligned.front(), w.t0, w.t1);
    for (const rig::TimeSeries& a : aligned) first.t = rig::times_inside(a, first.t);
    ChannelCurves& curves = result.curves;
    curves.t = first.t;
    curves.mean.assign(first.t.size(), 0.0);
    curves.low.assign(first.t.size(), std::numeric_limits<double>::infinity());
    curves.high.assign(first.t.size(), -std::numeric_limits<double>::infinity());
    for (const rig::TimeSeries& a : aligned) {
      const rig::TimeSeries at = rig::sample_at(a, first.t);
      for (std::size_t k = 0; k < at.t.size(); ++k) {
        curves.mean[k] += at.value[k] / static_cast<double>(aligned.size());
        curves.low[k] = std::min(curves.low[k], at.value[k]);
        curves.high[k] = std::max(curves.high[k], at.value[k]);
      }
    }
    const rig::TimeSeries sim_at = rig::sample_at(sim, curves.t);
    curves.simulated = sim_at.value;
    if (curves.t.size() < kMinScoredSamples)
      throw ScoringError(fmt::format(
          "channel '{}': the trials overlap in {} samples inside the window; a score needs {}",
          c.name, curves.t.size(), kMinScoredSamples));
    result.mean = score("mean", {curves.t, curves.mean}, sim_at, step0);
    out.channels.push_back(std::move(result));
  }
  return out;
}

}  // namespace ccm::bench
