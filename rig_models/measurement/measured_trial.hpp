// One measured benchtop trial, as read from its CSV (docs/measurements.md):
// one time series per sensor, each holding only the rows at which that sensor sampled.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "rig_models/signal/time_series.hpp"

namespace ccm::rig {

struct MeasuredTrial {
  std::filesystem::path source;
  std::string case_code;                        // RX025 ... FF100
  int trial = 0;                                // 1-based; 0 when the file does not say
  std::map<std::string, std::string> metadata;  // every "# key: value" line
  TimeSeries impactor_velocity_mps;             // V_i, m/s, positive toward the artifact
  TimeSeries artifact_angle_deg;                // theta_a, degrees
  TimeSeries pressure_kpa;                      // P, kPa
  std::vector<std::string> warnings;            // e.g. unknown columns, ignored
};

}  // namespace ccm::rig
