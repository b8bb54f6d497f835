// A piecewise-linear function of time given by (t, value) points; constant outside.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace ccm {

class TimeTable {
 public:
  TimeTable() = default;
  // Empty string when the points are usable (at least one, finite, strictly increasing t).
  static std::string validate(const std::vector<std::pair<double, double>>& points);
  explicit TimeTable(std::vector<std::pair<double, double>> points);

  double operator()(double t) const;

 private:
  std::vector<std::pair<double, double>> points_;
};

}  // namespace ccm
