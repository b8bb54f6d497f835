#include "app/validate_output.hpp"

#include <fmt/format.h>

#include <cmath>

#include "app/output_file.hpp"

namespace ccm {
namespace {

nlohmann::json score_json(const bench::ChannelScore& s, bool left_out) {
  nlohmann::json j = {{"against", s.against},
                      {"samples", s.samples},
                      {"nrmse", s.nrmse ? nlohmann::json(*s.nrmse) : nlohmann::json()},
                      {"peak_measured", s.peak_measured},
                      {"peak_simulated", s.peak_simulated},
                      {"peak_error", s.peak_error},
                      {"peak_time_error", s.peak_time_error}};
  if (left_out) j["left_out"] = true;
  const correlate::CurveRating& r = s.rating;
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
  const correlate::CurveRating& r = s.rating;
  const double rel = s.peak_measured != 0.0 ? s.peak_error / std::abs(s.peak_measured) : 0.0;
  fmt::print(
      "{:<14} {:<24} {:>7} {:>+7.1f}% {:>+8.3f} {:>6.3f} {:>6.3f} {:>6.3f} {:>6.3f} "
      "{:>7.3f}  {}\n",
      channel, left_out ? s.against + " (left out)" : s.against, nrmse_text(s.nrmse), 100.0 * rel,
      1e3 * s.peak_time_error, r.corridor, r.phase, r.magnitude, r.slope, r.overall,
      correlate::grade_name(r.grade));
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
    channels.push_back(
        {{"channel", c.channel}, {"mean", score_json(c.mean, false)}, {"trials", trials}});
  }
  return {
      {"iso18571_edition", "ISO/TS 18571:2024 procedure, default parameters (docs/correlation.md)"},
      {"clock_shifts", scores.clock_shifts},
      {"channels", channels}};
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
    print_score(c.channel, c.mean, false);
  }
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
