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

double median_step(const std::vector<double>& t) {
  std::vector<double> d;
  for (std::size_t k = 1; k < t.size(); ++k) d.push_back(t[k] - t[k - 1]);
  std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
  return d[d.size() / 2];
}

// Whether every step of `t` is `step` to the low-pass filter's tolerance (1e-6 relative): a
// uniform clock is kept as it is rather than interpolated onto itself.
bool uniform(const std::vector<double>& t, double step) {
  for (std::size_t k = 1; k < t.size(); ++k)
    if (std::abs(t[k] - t[k - 1] - step) > 1e-6 * step) return false;
  return true;
}

// The times t0, t0 + step, ... up to t1.
std::vector<double> uniform_times(double t0, double t1, double step) {
  std::vector<double> t;
  const auto n = static_cast<std::size_t>(std::floor((t1 - t0) / step * (1.0 + 1e-12))) + 1;
  // (the last one clamped: t0 + n step may round past t1 by an ulp)
  for (std::size_t k = 0; k < n; ++k) t.push_back(std::min(t1, t0 + static_cast<double>(k) * step));
  return t;
}

// A curve on a uniform clock of `step` over its own span (itself when it is on one already).
rig::TimeSeries on_uniform_clock(const rig::TimeSeries& s, double step) {
  if (uniform(s.t, step)) return s;
  return rig::sample_at(s, uniform_times(s.t.front(), s.t.back(), step));
}

void apply_deadband(rig::TimeSeries& s, double deadband) {
  if (deadband > 0.0)
    for (double& v : s.value)
      if (std::abs(v) < deadband) v = 0.0;
}

// The filter and the deadband of the channel (in the channel's order), on a uniformly sampled
// curve.
rig::TimeSeries conditioned(rig::TimeSeries s, double step, const ChannelSpec& c) {
  if (c.deadband_first) apply_deadband(s, c.deadband);
  if (c.filter.kind == FilterKind::cfc)
    s.value = correlate::cfc_filter(s.value, c.filter.frequency, step);
  else if (c.filter.kind == FilterKind::low_pass)
    s = rig::apply_low_pass(s, c.filter.frequency);
  if (!c.deadband_first) apply_deadband(s, c.deadband);
  return s;
}

// A curve on a uniform clock of `step` over its own span, then conditioned.
rig::TimeSeries uniform_conditioned(const rig::TimeSeries& s, double step, const ChannelSpec& c) {
  return conditioned(on_uniform_clock(s, step), step, c);
}

// The simulated curve conditioned for comparison with samples every `measured_step`: unfiltered,
// as it is (interpolated at the logger's instants when scored); where the simulation writes more
// often than the logger samples, filtered at its own rate first (sampling the unfiltered curve at
// the logger's instants would alias what lies above the logger's Nyquist frequency, as a logger's
// anti-aliasing filter does not let it); otherwise interpolated onto the logger's rate and
// filtered there.
rig::TimeSeries simulated_conditioned(const rig::TimeSeries& s, double measured_step,
                                      const ChannelSpec& c) {
  if (c.filter.kind == FilterKind::none) {
    rig::TimeSeries out = s;
    apply_deadband(out, c.deadband);
    return out;
  }
  const double own_step = median_step(s.t);
  if (own_step < measured_step) return uniform_conditioned(s, own_step, c);
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
  if (shift != 0.0)
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

// `measured` holds at least two samples, all inside the simulated span.
ChannelScore score(std::string against, const rig::TimeSeries& measured,
                   const rig::TimeSeries& simulated, double step) {
  const rig::TimeSeries sim_at = rig::sample_at(simulated, measured.t);
  const rig::ChannelComparison c = rig::compare_channel(measured, sim_at);
  ChannelScore s;
  s.against = std::move(against);
  s.samples = c.n_samples;
  s.rmse = c.rmse;
  s.nrmse = c.nrmse;
  s.peak_measured = c.peak_measured;
  s.peak_simulated = c.peak_simulated;
  s.peak_error = c.peak_error;
  s.peak_time_error = c.peak_time_error;
  // A measured curve that is zero everywhere has no corridor: no rating (a trial without contact
  // scored on its pressure), the other scores stand.
  const bool zero =
      std::all_of(measured.value.begin(), measured.value.end(), [](double v) { return v == 0.0; });
  if (measured.t.size() >= kMinRatedSamples && !zero)
    s.rating = correlate::iso18571_rating(measured.value, sim_at.value, step);
  return s;
}

struct Window {
  double t0, t1;
};

// The window inside the span of the conditioned simulated curve.
Window clipped(Window w, const rig::TimeSeries& sim) {
  return {std::max(w.t0, sim.t.front()), std::min(w.t1, sim.t.back())};
}

// The channel's window of numbers (or the whole span) inside the simulated span.
Window window_of(const ChannelSpec& c, const rig::TimeSeries& sim) {
  Window w{sim.t.front(), sim.t.back()};
  if (c.window) w = {(*c.window)[0], (*c.window)[1]};
  return clipped(w, sim);
}

// The trials' clocks shifted onto the simulation's: by the trigger, by the given offsets, or not.
std::vector<double> clock_shifts(const BenchMapping& m, const std::vector<PreparedTrial>& trials,
                                 const std::map<std::string, rig::TimeSeries>& simulated) {
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
  std::vector<double> shifts;
  for (std::size_t i = 0; i < trials.size(); ++i)
    shifts.push_back(sim_trigger               ? *sim_trigger - *trials[i].trigger_time
                     : m.align.offsets.empty() ? 0.0
                                               : m.align.offsets[i]);
  return shifts;
}

// Each trial's measured window of an event, on the simulation's clock (none without the event).
std::vector<std::optional<Window>> event_windows(const EventSpec& e,
                                                 const std::vector<PreparedTrial>& trials,
                                                 const std::vector<double>& shifts) {
  std::vector<std::optional<Window>> out;
  for (std::size_t i = 0; i < trials.size(); ++i) {
    const auto w =
        rig::first_contact(shifted(trials[i].channels.at(e.channel), shifts[i]), e.threshold);
    out.push_back(w ? std::optional<Window>(Window{w->onset, w->onset + w->duration})
                    : std::nullopt);
  }
  return out;
}

// The mean of the trials (and their spread) on the first one's samples inside `w` where every
// trial has samples.
ChannelCurves mean_curves(const std::vector<rig::TimeSeries>& aligned, Window w) {
  if (aligned.empty()) throw std::logic_error("a bench test has at least one trial");
  rig::TimeSeries first = within(aligned.front(), w.t0, w.t1);
  for (const rig::TimeSeries& a : aligned) first.t = rig::times_inside(a, first.t);
  ChannelCurves curves;
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
  return curves;
}

ScoringError too_few(const std::string& channel, const std::string& what, std::size_t n, Window w) {
  return ScoringError(fmt::format(
      "channel '{}': {} holds {} samples inside the simulated span and the window [{:.6g}, "
      "{:.6g}] s; a score needs {}",
      channel, what, n, w.t0, w.t1, kMinScoredSamples));
}

// A channel over its window of numbers or the whole simulated span: every trial and the mean
// hold kMinScoredSamples samples or more in it.
ChannelResult score_in_window(const ChannelSpec& c, const std::vector<PreparedTrial>& trials,
                              const std::vector<double>& shifts,
                              const std::map<std::string, rig::TimeSeries>& simulated) {
  // Conditioned for the first trial's rate; a trial at another rate gets its own below.
  const double step0 = trials[0].steps.at(c.name);
  const rig::TimeSeries sim = simulated_conditioned(simulated.at(c.name), step0, c);
  const Window w = window_of(c, sim);
  ChannelResult result;
  result.channel = c.name;
  std::vector<rig::TimeSeries> aligned;
  for (std::size_t i = 0; i < trials.size(); ++i) {
    const PreparedTrial& trial = trials[i];
    const double step = trial.steps.at(c.name);
    const rig::TimeSeries sim_u =
        step == step0 ? sim : simulated_conditioned(simulated.at(c.name), step, c);
    const Window wu = clipped(w, sim_u);
    aligned.push_back(shifted(trial.channels.at(c.name), shifts[i]));
    const rig::TimeSeries measured = within(aligned.back(), wu.t0, wu.t1);
    if (measured.t.size() < kMinScoredSamples)
      throw too_few(c.name, trial.name, measured.t.size(), w);
    result.trials.push_back(score(trial.name, measured, sim_u, step));
  }
  result.curves = mean_curves(aligned, w);
  result.curves.simulated = rig::sample_at(sim, result.curves.t).value;
  if (result.curves.t.size() < kMinScoredSamples)
    throw ScoringError(fmt::format(
        "channel '{}': the trials overlap in {} samples inside the window; a score needs {}",
        c.name, result.curves.t.size(), kMinScoredSamples));
  result.mean = score("mean", {result.curves.t, result.curves.mean}, sim, step0);
  return result;
}

// A channel inside each trial's own window of an event: the trials without the event, or with
// fewer than two samples in it, are not scored; the mean over the union of the trials' windows.
ChannelResult score_in_event(const ChannelSpec& c, const EventSpec& e,
                             const std::vector<PreparedTrial>& trials,
                             const std::vector<double>& shifts,
                             const std::map<std::string, rig::TimeSeries>& simulated) {
  const std::vector<std::optional<Window>> windows = event_windows(e, trials, shifts);
  const double step0 = trials[0].steps.at(c.name);
  const rig::TimeSeries sim = simulated_conditioned(simulated.at(c.name), step0, c);
  ChannelResult result;
  result.channel = c.name;
  std::vector<rig::TimeSeries> aligned;
  std::optional<Window> all;
  for (std::size_t i = 0; i < trials.size(); ++i) {
    aligned.push_back(shifted(trials[i].channels.at(c.name), shifts[i]));
    if (!windows[i]) continue;
    const double step = trials[i].steps.at(c.name);
    const rig::TimeSeries sim_u =
        step == step0 ? sim : simulated_conditioned(simulated.at(c.name), step, c);
    const Window wu = clipped(*windows[i], sim_u);
    all = all ? Window{std::min(all->t0, wu.t0), std::max(all->t1, wu.t1)} : wu;
    const rig::TimeSeries measured = within(aligned.back(), wu.t0, wu.t1);
    if (measured.t.size() >= kMinScoredSamples)
      result.trials.push_back(score(trials[i].name, measured, sim_u, step));
  }
  if (!all) return result;
  result.curves = mean_curves(aligned, *all);
  result.curves.simulated = rig::sample_at(sim, result.curves.t).value;
  if (result.curves.t.size() >= kMinScoredSamples)
    result.mean = score("mean", {result.curves.t, result.curves.mean}, sim, step0);
  return result;
}

// The event in each trial and in the simulation conditioned alike, at the trial's instants.
EventResult score_event(const BenchMapping& m, const EventSpec& e,
                        const std::vector<PreparedTrial>& trials, const std::vector<double>& shifts,
                        const std::map<std::string, rig::TimeSeries>& simulated) {
  const ChannelSpec& c = *m.channel(e.channel);
  EventResult out;
  out.event = e.name;
  for (std::size_t i = 0; i < trials.size(); ++i) {
    const rig::TimeSeries sim =
        simulated_conditioned(simulated.at(c.name), trials[i].steps.at(c.name), c);
    out.trials.push_back(trials[i].name);
    out.per_trial.push_back(
        rig::compare_contact(shifted(trials[i].channels.at(c.name), shifts[i]), sim, e.threshold));
  }
  return out;
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
            c.condition_measured ? uniform_conditioned(raw, step, c) : on_uniform_clock(raw, step);
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
  if (trials.empty()) throw std::logic_error("a bench test has at least one trial");
  BenchScores out;
  out.clock_shifts = clock_shifts(m, trials, simulated);
  for (const ChannelSpec& c : m.channels)
    out.channels.push_back(
        c.window_event
            ? score_in_event(c, *m.event(*c.window_event), trials, out.clock_shifts, simulated)
            : score_in_window(c, trials, out.clock_shifts, simulated));
  for (const EventSpec& e : m.events)
    out.events.push_back(score_event(m, e, trials, out.clock_shifts, simulated));
  return out;
}

}  // namespace ccm::bench
