#include "rig_models/measurement/clock_jump.hpp"

#include <algorithm>
#include <vector>

namespace ccm::rig {

std::optional<ClockJump> find_clock_jump(std::span<const double> row_times, double factor) {
  if (row_times.size() < 3) return std::nullopt;
  std::vector<double> steps;
  for (std::size_t k = 1; k < row_times.size(); ++k)
    steps.push_back(row_times[k] - row_times[k - 1]);
  std::vector<double> sorted = steps;
  const auto middle = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2);
  std::nth_element(sorted.begin(), middle, sorted.end());
  const double median = *middle;
  for (std::size_t k = 0; k < steps.size(); ++k)
    if (steps[k] > factor * median) return ClockJump{k + 1, steps[k], median};
  return std::nullopt;
}

}  // namespace ccm::rig
