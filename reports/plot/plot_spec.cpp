#include "reports/plot/plot_spec.hpp"

#include <algorithm>

namespace ccm::reports {

bool spans_decades(std::span<const double> values) {
  if (values.empty()) return false;
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  return *lo > 0.0 && *hi >= 100.0 * *lo;
}

std::vector<double> all_values(const PlotSpec& plot, int axis) {
  std::vector<double> out;
  for (const Series& s : plot.series) {
    const auto& v = axis == 0 ? s.x : axis == 1 ? s.y : s.z;
    out.insert(out.end(), v.begin(), v.end());
    // A 2-D band or mark spans y .. z: both ends are y values.
    if (axis == 1 && !plot.three_d &&
        (s.style == SeriesStyle::band || s.style == SeriesStyle::marks))
      out.insert(out.end(), s.z.begin(), s.z.end());
  }
  return out;
}

}  // namespace ccm::reports
