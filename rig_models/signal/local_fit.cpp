#include "rig_models/signal/local_fit.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <stdexcept>

namespace ccm::rig {

LocalFit local_quadratic_fit(const TimeSeries& signal, double half_window) {
  check_time_series(signal, "local fit input", 4);
  if (!(half_window > 0.0))
    throw std::invalid_argument(
        fmt::format("local fit: half window must be > 0 (got {})", half_window));
  const std::vector<double>& t = signal.t;
  LocalFit out{{t, std::vector<double>(t.size())}, {t, std::vector<double>(t.size())}};
  size_t lo = 0, hi = 0;  // the window [lo, hi) slides with k
  for (size_t k = 0; k < t.size(); ++k) {
    while (t[lo] < t[k] - half_window) ++lo;
    while (hi < t.size() && t[hi] <= t[k] + half_window) ++hi;
    // Near the ends (or a gap) the window takes the nearest samples until it holds four.
    size_t a = lo, b = hi;
    while (b - a < 4 && (a > 0 || b < t.size())) {
      const bool left = a > 0 && (b == t.size() || t[k] - t[a - 1] <= t[b] - t[k]);
      left ? --a : ++b;
    }
    const size_t n = b - a;
    if (n < 4)
      throw std::invalid_argument(
          fmt::format("local fit: {} samples in all; at least 4 needed", t.size()));
    // Scaled abscissa s = (t - t_k) / half_window keeps the normal equations well conditioned.
    Eigen::MatrixXd A(static_cast<Eigen::Index>(n), 3);
    Eigen::VectorXd y(static_cast<Eigen::Index>(n));
    for (size_t j = 0; j < n; ++j) {
      const double s = (t[a + j] - t[k]) / half_window;
      A.row(static_cast<Eigen::Index>(j)) << 1.0, s, s * s;
      y(static_cast<Eigen::Index>(j)) = signal.value[a + j];
    }
    const Eigen::Vector3d c = A.colPivHouseholderQr().solve(y);
    out.value.value[k] = c(0);
    out.derivative.value[k] = c(1) / half_window;
  }
  return out;
}

}  // namespace ccm::rig
