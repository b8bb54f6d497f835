#include "reports/figures/rig_channel_figures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <span>
#include <stdexcept>

#include "rig_models/compare/trial_ensemble.hpp"

namespace ccm::reports {
namespace {

struct Channel {
  const char* key;         // figure id part
  const char* name;        // in the caption
  const char* axis_label;  // with unit
  rig::TimeSeries rig::RigChannels::*series;
};

constexpr Channel kChannels[] = {
    {"velocity", "impactor velocity V_i", "impactor velocity V_i [m/s]",
     &rig::RigChannels::impactor_velocity_mps},
    {"angle", "artifact angle theta_a", "artifact angle theta_a [deg]",
     &rig::RigChannels::artifact_angle_deg},
    {"pressure", "sensor pressure P", "sensor pressure P [kPa]", &rig::RigChannels::pressure_kpa},
};

constexpr int kSimulationColour = 1, kBandColour = 0, kMeasuredMarkColour = 6,
              kSimulatedMarkColour = 4;
constexpr int kTrialColours[] = {5, 2, 3};

std::string model_label(const db::RigRunRow& row) {
  return fmt::format("ccm rig model, {} drive", row.drive);
}

std::string lower_id(std::string text) {
  for (char& c : text)
    c = std::isalnum(static_cast<unsigned char>(c))
            ? static_cast<char>(std::tolower(static_cast<unsigned char>(c)))
            : '-';
  return text;
}

Series band_series(std::span<const rig::TimeSeries> trials, const std::string& label) {
  Series band{.title = label, .style = SeriesStyle::band, .color = kBandColour};
  if (trials.size() < 2) return band;
  try {
    const rig::ChannelEnsemble e = rig::channel_ensemble(trials);
    for (size_t k = 0; k < e.mean.t.size(); ++k) {
      band.x.push_back(e.mean.t[k]);
      band.y.push_back(e.mean.value[k] - e.spread[k]);
      band.z.push_back(e.mean.value[k] + e.spread[k]);
    }
  } catch (const std::invalid_argument&) {
    // No common time: the trials are drawn, the band is left out.
  }
  return band;
}

// Dashed vertical marks at the contact onsets and ends, over the plot's y range.
Series marks_series(const std::vector<double>& times, std::string title, int colour,
                    const PlotSpec& plot) {
  Series s{.title = std::move(title), .style = SeriesStyle::marks, .color = colour};
  const std::vector<double> y = all_values(plot, 1);
  if (times.empty() || y.empty()) return s;
  auto [lo, hi] = std::minmax_element(y.begin(), y.end());
  const double pad = *hi > *lo ? 0.0 : 1.0;
  for (double t : times) {
    s.x.push_back(t);
    s.y.push_back(*lo - pad);
    s.z.push_back(*hi + pad);
  }
  return s;
}

struct ContactTimes {
  std::vector<double> measured, simulated;
};

ContactTimes contact_times(const db::RigRunRecord& r) {
  ContactTimes out;
  if (!r.comparison) return out;
  for (const rig::ContactComparison& c : r.comparison->contact) {
    if (c.measured)
      out.measured.insert(out.measured.end(),
                          {c.measured->onset, c.measured->onset + c.measured->duration});
    if (c.simulated && out.simulated.empty())
      out.simulated = {c.simulated->onset, c.simulated->onset + c.simulated->duration};
  }
  return out;
}

Figure channel_figure(const db::StoredRigRun& run, const Channel& ch) {
  const db::RigRunRecord& r = run.record;
  const std::string who = rig_case_label(r.row);
  PlotSpec plot{.title = fmt::format("{}: {}", who, ch.name),
                .x_label = "trial time [s]",
                .y_label = ch.axis_label,
                .height = 520};  // room for the seven legend lines below the plot
  std::vector<rig::TimeSeries> measured;
  for (const rig::RigChannels& m : r.measured_channels) measured.push_back(m.*ch.series);
  plot.series.push_back(band_series(
      measured,
      fmt::format("measured mean +/- 1 sd, {}, {}", r.row.case_code, trials_label(r.trials))));
  for (size_t j = 0; j < measured.size(); ++j)
    plot.series.push_back(
        Series{.title = fmt::format("measured, {}, trial {}", r.row.case_code, r.trials.at(j)),
               .style = SeriesStyle::thin_lines,
               .x = measured[j].t,
               .y = measured[j].value,
               .color = kTrialColours[j % std::size(kTrialColours)]});
  const rig::TimeSeries& sim = r.channels.*ch.series;
  plot.series.push_back(Series{.title = fmt::format("simulated, {}, {} (run {})", r.row.case_code,
                                                    model_label(r.row), run.id),
                               .style = SeriesStyle::lines,
                               .x = sim.t,
                               .y = sim.value,
                               .color = kSimulationColour});
  const ContactTimes contact = contact_times(r);
  Series measured_marks = marks_series(
      contact.measured,
      fmt::format("measured contact onset/end, {}, {}", r.row.case_code, trials_label(r.trials)),
      kMeasuredMarkColour, plot);
  Series simulated_marks = marks_series(
      contact.simulated,
      fmt::format("simulated contact onset/end, {}, {}", r.row.case_code, model_label(r.row)),
      kSimulatedMarkColour, plot);
  // The measured marks drawn last: on top where the simulated ones coincide with them.
  plot.series.push_back(std::move(simulated_marks));
  plot.series.push_back(std::move(measured_marks));
  const std::string trials_text =
      measured.empty() ? "the measured trials are not in this store (it was written before ccm "
                         "stored them)"
                       : fmt::format("the measured {}", trials_label(r.trials));
  return make_figure(
      fmt::format("fig-rig-{}-{}-{}", lower_id(r.row.case_code), lower_id(r.row.drive), ch.key),
      fmt::format("{}: {} of the simulation (run {}, {}) against {}; band: mean +/- one sample "
                  "standard deviation over the trials; dashed: contact onset and end, measured "
                  "and simulated (thesis Figs. 3-23 ... 3-37).",
                  who, ch.name, run.id, r.row.status, trials_text),
      std::move(plot));
}

}  // namespace

std::string rig_case_label(const db::RigRunRow& row) {
  return fmt::format("{} ({} drive)", row.case_code, row.drive);
}

std::string trials_label(const std::vector<int>& trials) {
  if (trials.empty()) return "no trial";
  std::string out = trials.size() == 1 ? "trial " : "trials ";
  for (size_t k = 0; k < trials.size(); ++k) out += fmt::format("{}{}", k ? ", " : "", trials[k]);
  return out;
}

std::vector<Figure> rig_channel_figures(const db::StoredRigRun& run) {
  std::vector<Figure> out;
  for (const Channel& ch : kChannels) {
    Figure f = channel_figure(run, ch);
    if (!all_values(f.plot, 0).empty()) out.push_back(std::move(f));
  }
  return out;
}

}  // namespace ccm::reports
