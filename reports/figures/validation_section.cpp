#include "reports/figures/validation_section.hpp"

#include <fmt/format.h>

#include <cmath>
#include <sstream>
#include <string>

namespace ccm::reports {
namespace {

constexpr int kSimulationColour = 1, kBandColour = 0, kMeanColour = 5;

struct Curves {
  std::vector<double> t, simulated, mean, low, high;
};

// The stored CSV (time,simulated,mean,low,high), header skipped.
Curves parse_curves(const std::string& csv) {
  Curves c;
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::istringstream cells(line);
    std::string cell;
    std::vector<double> v;
    while (std::getline(cells, cell, ',')) v.push_back(std::stod(cell));
    if (v.size() != 5) continue;
    c.t.push_back(v[0]);
    c.simulated.push_back(v[1]);
    c.mean.push_back(v[2]);
    c.low.push_back(v[3]);
    c.high.push_back(v[4]);
  }
  return c;
}

Figure channel_figure(const db::ValidationRow& v, std::size_t index,
                      const db::ValidationCurvesRow& row) {
  const Curves c = parse_curves(row.curves_csv);
  PlotSpec plot{.title = fmt::format("{}: {}", v.scene, row.channel),
                .x_label = "simulation time [s]",
                .y_label = fmt::format("{} [{}]", row.channel, row.unit)};
  plot.series.push_back(Series{.title = "trials: lowest to highest",
                               .style = SeriesStyle::band,
                               .x = c.t,
                               .y = c.low,
                               .z = c.high,
                               .color = kBandColour});
  plot.series.push_back(Series{.title = "trials' mean",
                               .style = SeriesStyle::thin_lines,
                               .x = c.t,
                               .y = c.mean,
                               .color = kMeanColour});
  plot.series.push_back(Series{.title = fmt::format("simulated ({})", v.scene),
                               .style = SeriesStyle::lines,
                               .x = c.t,
                               .y = c.simulated,
                               .color = kSimulationColour});
  return make_figure(fmt::format("fig-validation-{}-{}", index + 1, row.channel),
                     fmt::format("Validation {} ({}, recorded {} UTC): channel {} of the "
                                 "simulation against the bench test {}, both filtered alike and "
                                 "on the trials' aligned clocks; band: the trials' lowest to "
                                 "highest value at each sample.",
                                 index + 1, v.scene, v.recorded_at, row.channel, v.data),
                     std::move(plot));
}

std::string optional_cell(const std::optional<double>& v) {
  return v ? fmt::format("{:.3f}", *v) : std::string("-");
}

Table rating_table(const db::ValidationRow& v, std::size_t index) {
  Table t{.id = fmt::format("validation-{}", index + 1),
          .caption = fmt::format(
              "Validation {}: {} against {} (ISO/TS 18571: Z corridor, E_P phase, E_M "
              "magnitude, E_S slope, R = 0.4 Z + 0.2 (E_P + E_M + E_S); docs/correlation.md){}",
              index + 1, v.scene, v.data,
              v.fitted.empty() ? "" : "; fitted with " + v.fitted + ", left-out trials marked"),
          .header = {"channel", "against", "nRMSE", "peak error", "time-of-peak error [ms]", "Z",
                     "E_P", "E_M", "E_S", "rating R", "grade"}};
  for (const db::ValidationScoreRow& s : v.scores) {
    const double rel = s.peak_measured != 0.0
                           ? (s.peak_simulated - s.peak_measured) / std::abs(s.peak_measured)
                           : 0.0;
    t.rows.push_back({s.channel, s.left_out ? s.against + " (left out)" : s.against,
                      optional_cell(s.nrmse), fmt::format("{:+.1f} %", 100.0 * rel),
                      fmt::format("{:+.3f}", 1e3 * s.peak_time_error),
                      fmt::format("{:.3f}", s.corridor), fmt::format("{:.3f}", s.phase),
                      fmt::format("{:.3f}", s.magnitude), fmt::format("{:.3f}", s.slope),
                      fmt::format("{:.3f}", s.rating), s.grade});
  }
  return t;
}

}  // namespace

Section validation_section(const std::vector<db::ValidationRow>& validations) {
  Section s{.id = "bench-tests", .title = "Your bench tests"};
  if (validations.empty()) {
    s.paragraphs.push_back(
        "No bench test validated yet: `ccm validate SCENE --data FOLDER --db THIS_STORE` runs a "
        "scene once and rates it against the trials of your own bench test, channel by channel, "
        "and records the ratings here (docs/bench-test.md).");
    return s;
  }
  s.paragraphs.push_back(fmt::format(
      "{} validation{} of a scene against a bench test (`ccm validate`): each channel against each "
      "trial and against the trials' mean, by nRMSE (by the measured range), the peak and its "
      "time, and the ISO/TS 18571 objective rating with its grade (excellent above 0.94, good "
      "above 0.80, fair above 0.58, else poor).",
      validations.size(), validations.size() == 1 ? "" : "s"));
  for (std::size_t i = 0; i < validations.size(); ++i) {
    s.tables.push_back(rating_table(validations[i], i));
    for (const db::ValidationCurvesRow& c : validations[i].curves)
      s.figures.push_back(channel_figure(validations[i], i, c));
  }
  return s;
}

}  // namespace ccm::reports
