#include "app/validate_output.hpp"

#include <fmt/format.h>

#include <cmath>

#include "app/output_file.hpp"

namespace ccm {
namespace {

nlohmann::json score_json(const bench::ChannelScore& s, bool left_out) {
  nlohmann::json j = {{"against", s.against},
                      {"samples", s.samples},
                      {"rmse", s.rmse},
                      {"nrmse", s.nrmse ? nlohmann::json(*s.nrmse) : nlohmann::json()},
                      {"peak_measured", s.peak_measured},
                      {"peak_simulated", s.peak_simulated},
                      {"peak_error", s.peak_error},
                      {"peak_time_error", s.peak_time_error}};
  if (left_out) j["left_out"] = true;
  if (!s.rating) {
    j["iso18571"] = nlohmann::json();  // fewer samples than a rating needs
    return j;
  }
  const correlate::CurveRating& r = *s.rating;
  j["iso18571"] = {{"corridor", r.corridor},
                   {"phase", r.phase},
                   {"magnitude", r.magnitude},
                   {"slope", r.slope},
                   {"overall", r.overall},
                   {"grade", correlate::grade_name(r.grade)},
                   {"shift_samples", r.shift_samples}};
  return j;
}

std::string nrmse_text(const std::optional<double>& v) {
  return v ? fmt::format("{:.3f}", *v) : std::string("-");
}

void print_score(const std::string& channel, const bench::ChannelScore& s, bool left_out) {
  const double rel = s.peak_measured != 0.0 ? s.peak_error / std::abs(s.peak_measured) : 0.0;
  fmt::print("{:<14} {:<24} {:>7} {:>+7.1f}% {:>+8.3f} ", channel,
             left_out ? s.against + " (left out)" : s.against, nrmse_text(s.nrmse), 100.0 * rel,
             1e3 * s.peak_time_error);
  if (!s.rating) {
    fmt::print("{:>6} {:>6} {:>6} {:>6} {:>7}  unrated ({} samples)\n", "-", "-", "-", "-", "-",
               s.samples);
    return;
  }
  const correlate::CurveRating& r = *s.rating;
  fmt::print("{:>6.3f} {:>6.3f} {:>6.3f} {:>6.3f} {:>7.3f}  {}\n", r.corridor, r.phase, r.magnitude,
             r.slope, r.overall, correlate::grade_name(r.grade));
}

nlohmann::json event_json(const bench::EventResult& e) {
  nlohmann::json trials = nlohmann::json::array();
  auto window = [](const std::optional<rig::ContactWindow>& w) {
    return w ? nlohmann::json{{"onset", w->onset},
                              {"duration", w->duration},
                              {"released", w->released}}
             : nlohmann::json();
  };
  auto value = [](const std::optional<double>& v) {
    return v ? nlohmann::json(*v) : nlohmann::json();
  };
  for (std::size_t i = 0; i < e.trials.size(); ++i) {
    const rig::ContactComparison& c = e.per_trial[i];
    trials.push_back({{"against", e.trials[i]},
                      {"measured", window(c.measured)},
                      {"simulated", window(c.simulated)},
                      {"onset_error", value(c.onset_error)},
                      {"duration_error", value(c.duration_error)}});
  }
  return {{"event", e.event}, {"trials", trials}};
}

std::string ms_text(const std::optional<double>& v) {
  return v ? fmt::format("{:+.2f}", 1e3 * *v) : std::string("-");
}

void print_event(const bench::EventResult& e) {
  for (std::size_t i = 0; i < e.trials.size(); ++i) {
    const rig::ContactComparison& c = e.per_trial[i];
    auto ms = [](const std::optional<rig::ContactWindow>& w) {
      return w ? fmt::format("{:.2f} + {:.2f}", 1e3 * w->onset, 1e3 * w->duration)
               : std::string("none");
    };
    fmt::print("{:<14} {:<24} {:>18} {:>18} {:>9} {:>9}\n", e.event, e.trials[i], ms(c.measured),
               ms(c.simulated), ms_text(c.onset_error), ms_text(c.duration_error));
  }
}

}  // namespace

std::optional<bench::BenchScores> scored(const bench::BenchMapping& mapping,
                                         const std::vector<bench::PreparedTrial>& trials,
                                         const std::map<std::string, rig::TimeSeries>& simulated) {
  try {
    return bench::score_bench_test(mapping, trials, simulated);
  } catch (const bench::ScoringError& e) {
    fmt::print(stderr, "ccm: the run cannot be scored against the trials: {}\n", e.what());
    return std::nullopt;
  }
}

nlohmann::json scores_json(const bench::BenchScores& scores,
                           const std::set<std::string>& left_out) {
  nlohmann::json channels = nlohmann::json::array();
  for (const bench::ChannelResult& c : scores.channels) {
    nlohmann::json trials = nlohmann::json::array();
    for (const bench::ChannelScore& s : c.trials)
      trials.push_back(score_json(s, left_out.count(s.against) > 0));
    channels.push_back({{"channel", c.channel},
                        {"mean", c.mean ? score_json(*c.mean, false) : nlohmann::json()},
                        {"trials", trials}});
  }
  nlohmann::json events = nlohmann::json::array();
  for (const bench::EventResult& e : scores.events) events.push_back(event_json(e));
  return {
      {"iso18571_edition", "ISO/TS 18571:2024 procedure, default parameters (docs/correlation.md)"},
      {"clock_shifts", scores.clock_shifts},
      {"channels", channels},
      {"events", events}};
}

void print_scores(const bench::BenchScores& scores, const std::set<std::string>& left_out) {
  fmt::print("clock shifts onto the simulation [ms]:");
  for (double s : scores.clock_shifts) fmt::print(" {:+.3f}", 1e3 * s);
  fmt::print("\n\n{:<14} {:<24} {:>7} {:>8} {:>8} {:>6} {:>6} {:>6} {:>6} {:>7}  {}\n", "channel",
             "against", "nRMSE", "peak err", "t_pk ms", "Z", "E_P", "E_M", "E_S", "rating",
             "grade");
  for (const bench::ChannelResult& c : scores.channels) {
    for (const bench::ChannelScore& s : c.trials)
      print_score(c.channel, s, left_out.count(s.against) > 0);
    if (c.mean) print_score(c.channel, *c.mean, false);
  }
  if (scores.events.empty()) return;
  fmt::print("\n{:<14} {:<24} {:>18} {:>18} {:>9} {:>9}\n", "event", "against", "measured ms",
             "simulated ms", "onset err", "dur err");
  for (const bench::EventResult& e : scores.events) print_event(e);
}

std::string channel_curves_csv(const bench::ChannelCurves& c) {
  std::string csv = "time,simulated,mean,low,high\n";
  for (std::size_t k = 0; k < c.t.size(); ++k)
    csv += fmt::format("{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", c.t[k], c.simulated[k],
                       c.mean[k], c.low[k], c.high[k]);
  return csv;
}

void write_channel_curves(const std::filesystem::path& out, const bench::BenchScores& scores) {
  for (const bench::ChannelResult& r : scores.channels)
    write_atomic(out / (r.channel + ".csv"), channel_curves_csv(r.curves));
}

}  // namespace ccm
