#include "rig_models/signal/time_series.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace ccm::rig {

void check_time_series(const TimeSeries& s, std::string_view what, size_t min_samples) {
  if (s.t.size() != s.value.size())
    throw std::invalid_argument(
        fmt::format("{}: {} times but {} values", what, s.t.size(), s.value.size()));
  if (s.t.size() < min_samples)
    throw std::invalid_argument(
        fmt::format("{}: {} samples, at least {} needed", what, s.t.size(), min_samples));
  for (size_t i = 0; i < s.t.size(); ++i) {
    if (!std::isfinite(s.t[i]) || !std::isfinite(s.value[i]))
      throw std::invalid_argument(fmt::format("{}: sample {} is not finite", what, i));
    if (i > 0 && !(s.t[i] > s.t[i - 1]))
      throw std::invalid_argument(
          fmt::format("{}: time {} s at sample {} does not increase", what, s.t[i], i));
  }
}

}  // namespace ccm::rig
