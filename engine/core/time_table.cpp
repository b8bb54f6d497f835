#include "engine/core/time_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ccm {

std::string TimeTable::validate(const std::vector<std::pair<double, double>>& points) {
  if (points.empty()) return "needs at least one [t, value] point";
  for (size_t i = 0; i < points.size(); ++i) {
    if (!std::isfinite(points[i].first) || !std::isfinite(points[i].second))
      return fmt::format("point {} is not finite", i + 1);
    if (i > 0 && !(points[i].first > points[i - 1].first))
      return fmt::format("times must increase strictly (point {})", i + 1);
  }
  return {};
}

TimeTable::TimeTable(std::vector<std::pair<double, double>> points) : points_(std::move(points)) {
  if (const std::string why = validate(points_); !why.empty()) throw std::invalid_argument(why);
}

double TimeTable::operator()(double t) const {
  if (t <= points_.front().first) return points_.front().second;
  if (t >= points_.back().first) return points_.back().second;
  const auto hi = std::upper_bound(points_.begin(), points_.end(), t,
                                   [](double v, const auto& p) { return v < p.first; });
  const auto lo = hi - 1;
  const double s = (t - lo->first) / (hi->first - lo->first);
  return lo->second + s * (hi->second - lo->second);
}

}  // namespace ccm
