// Comparing one channel (V_i, theta_a or P) of a simulation with a measurement: the
// simulation is sampled at the measurement's timestamps (linear interpolation, only where the
// two overlap), then
//   RMSE   = sqrt( (1/N) sum_k (s_k - m_k)^2 )
//   nRMSE  = RMSE / (max_k m_k - min_k m_k)          (normalised by the measured range)
//   peak   = the sample of largest |value| in each (sign kept), peak error s - m and
//            peak-time error t_s - t_m, both on the measurement's timestamps.
// Contact (from the pressure channel): onset = first sample at or above the contact
// threshold; duration = from onset to the first later sample below it (the first contact
// event; a contact still on at the last sample ends there and is flagged).
#pragma once

#include <optional>

#include "rig_models/signal/time_series.hpp"

namespace ccm::rig {

struct ChannelComparison {
  size_t n_samples = 0;         // measurement samples inside the simulated time span
  double rmse = 0.0;            // channel unit
  std::optional<double> nrmse;  // none when the measured channel is constant
  double peak_measured = 0.0;   // channel unit
  double peak_simulated = 0.0;
  double peak_error = 0.0;       // simulated - measured
  double peak_time_error = 0.0;  // s, simulated - measured
};

// Throws std::invalid_argument when fewer than two measurement samples overlap the simulation.
ChannelComparison compare_channel(const TimeSeries& measured, const TimeSeries& simulated);

// The same on the measurement's samples inside [t0, t1] alone (both ends included; peaks and
// the range of nRMSE are those inside it). None when fewer than two of them lie there and in the
// simulated span.
std::optional<ChannelComparison> compare_channel_within(const TimeSeries& measured,
                                                        const TimeSeries& simulated, double t0,
                                                        double t1);

struct ContactWindow {
  double onset = 0.0;     // s
  double duration = 0.0;  // s
  bool released = true;   // false when still in contact at the last sample
};

// The first contact event of a pressure signal, none when it never reaches the threshold.
// Throws std::invalid_argument unless threshold > 0 (the deadband makes "non-zero" the
// measured criterion; a filtered simulation never returns exactly to zero).
std::optional<ContactWindow> first_contact(const TimeSeries& pressure, double threshold);

struct ContactComparison {
  std::optional<ContactWindow> measured;
  std::optional<ContactWindow> simulated;
  std::optional<double> onset_error;     // s, simulated - measured, when both have contact
  std::optional<double> duration_error;  // s, simulated - measured
};

// Both pressures on the measurement's timestamps (the simulation sampled there first).
ContactComparison compare_contact(const TimeSeries& measured_pressure,
                                  const TimeSeries& simulated_pressure, double threshold);

}  // namespace ccm::rig
