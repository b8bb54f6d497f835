// A sampled signal: plain time and value vectors, the common currency of the rig's
// post-processing (measured channels and sampled simulation histories alike).
#pragma once

#include <string_view>
#include <vector>

namespace ccm::rig {

struct TimeSeries {
  std::vector<double> t;      // s, strictly increasing
  std::vector<double> value;  // in the channel's unit
};

// Throws std::invalid_argument naming `what` unless t and value have the same size, at least
// `min_samples` samples, every number is finite and t strictly increases.
void check_time_series(const TimeSeries& s, std::string_view what, size_t min_samples = 1);

}  // namespace ccm::rig
