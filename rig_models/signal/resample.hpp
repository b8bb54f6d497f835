// Sampling a signal at other times (the simulation at the measurement's timestamps, one
// trial on another's), by linear interpolation; never extrapolated.
#pragma once

#include <span>

#include "rig_models/signal/time_series.hpp"

namespace ccm::rig {

// The signal linearly interpolated at `times` (increasing). Throws std::invalid_argument when
// a time lies outside [signal.t.front(), signal.t.back()].
TimeSeries sample_at(const TimeSeries& signal, std::span<const double> times);

// The times of `times` that lie inside [signal.t.front(), signal.t.back()].
std::vector<double> times_inside(const TimeSeries& signal, std::span<const double> times);

}  // namespace ccm::rig
