#include "rig_models/signal/deadband.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace ccm::rig {

TimeSeries apply_deadband(const TimeSeries& signal, double threshold) {
  if (!(threshold >= 0.0) || !std::isfinite(threshold))
    throw std::invalid_argument(
        fmt::format("deadband: threshold must be finite and >= 0 (got {})", threshold));
  TimeSeries out = signal;
  for (double& v : out.value)
    if (v < threshold) v = 0.0;
  return out;
}

}  // namespace ccm::rig
