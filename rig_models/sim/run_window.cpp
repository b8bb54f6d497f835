#include "rig_models/sim/run_window.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rig_models/compare/channel_metrics.hpp"
#include "rig_models/drive/open_loop_drive.hpp"
#include "rig_models/signal/local_fit.hpp"
#include "rig_models/signal/resample.hpp"

namespace ccm::rig {
namespace {

double trial_end(const MeasuredTrial& m) {
  return std::min(
      {m.impactor_velocity_mps.t.back(), m.artifact_angle_deg.t.back(), m.pressure_kpa.t.back()});
}

double round_end(double start, double end, double interval) {
  const double n = std::floor((end - start) / interval + 1e-9);
  return start + n * interval;
}

}  // namespace

double measured_onset(const MeasuredTrial& m, double threshold) {
  const auto contact = first_contact(m.pressure_kpa, threshold);
  if (!contact)
    throw std::invalid_argument(fmt::format(
        "{}: no measured contact (the pressure never reaches the {} kPa deadband); the drive "
        "needs one",
        m.source.string(), threshold));
  return contact->onset;
}

RunWindow run_window(const RigCaseTable& table, const RigCase& c, const WindowRequest& req,
                     const HangingWeightSettings& weight, const TrackFrictionSpec& track) {
  const double interval = table.simulation.output_interval.value;
  RunWindow w;
  if (!req.trial) {
    if (req.drive == DriveKind::open_loop)
      throw std::invalid_argument(
          "the open-loop drive follows a measured trial: give --data DIR (and --trial N), or use "
          "--drive physical");
    if (req.start)
      throw std::invalid_argument("--start: a physical run starts at the release, t = 0");
    w.gap = run_up_distance(weight, track, table.rig.impactor_mass.value, c.target_speed.value);
    // Time to cover the gap from rest, about 2 gap / v for a nearly uniform acceleration.
    const double contact = 2.0 * w.gap / c.target_speed.value;
    w.end =
        round_end(0.0, req.end.value_or(contact + table.simulation.after_contact.value), interval);
    if (!(w.end > 0.0)) throw std::invalid_argument("--end must be > 0");
    return w;
  }
  const MeasuredTrial& m = *req.trial;
  w.measured_onset = measured_onset(m, table.rig.sensor_deadband.value);
  const LocalFit fit =
      local_quadratic_fit(m.impactor_velocity_mps, table.drive.velocity_smoothing.value);
  const double t_first = fit.value.t.front();
  if (req.drive == DriveKind::physical) {
    if (req.start)
      throw std::invalid_argument("--start: a physical run starts at the release, t = 0");
    w.start = 0.0;
    w.gap = travel(fit.value, std::max(0.0, t_first), *w.measured_onset);
  } else {
    w.start =
        req.start.value_or(std::max(t_first, *w.measured_onset - table.simulation.lead.value));
    if (w.start < t_first || !(w.start < *w.measured_onset))
      throw std::invalid_argument(fmt::format(
          "--start {} s: the open-loop run must start inside the trial ({} s on) and before its "
          "contact at {} s",
          w.start, t_first, *w.measured_onset));
    w.gap = travel(fit.value, w.start, *w.measured_onset);
    w.initial_velocity = sample_at(fit.value, std::vector<double>{w.start}).value[0];
  }
  const double last = trial_end(m);
  w.end = round_end(w.start, std::min(req.end.value_or(last), last), interval);
  if (!(w.end > w.start + interval))
    throw std::invalid_argument(
        fmt::format("--end: the window [{}, {}] s is empty", w.start, w.end));
  if (!(w.gap > 0.0))
    throw std::invalid_argument(fmt::format(
        "{}: the measured velocity covers no distance before the contact at {} s (gap {} m)",
        m.source.string(), *w.measured_onset, w.gap));
  return w;
}

}  // namespace ccm::rig
