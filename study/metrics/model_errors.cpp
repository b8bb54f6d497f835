#include "study/metrics/model_errors.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

namespace ccm::study {

namespace {

void require_paired(std::span<const double> ccm, std::span<const double> rigid) {
  if (ccm.empty() || ccm.size() != rigid.size())
    throw std::invalid_argument("model errors need two non-empty histories of equal length (ccm " +
                                std::to_string(ccm.size()) + ", rigid " +
                                std::to_string(rigid.size()) + " samples)");
}

void require_times(std::span<const double> time, std::size_t n) {
  if (time.size() != n || n < 2)
    throw std::invalid_argument(
        "cumulative error needs at least two samples and one time per "
        "sample (" +
        std::to_string(time.size()) + " times, " + std::to_string(n) + " samples)");
  for (std::size_t i = 1; i < n; ++i)
    if (!(time[i] > time[i - 1]))
      throw std::invalid_argument("cumulative error: sample times must increase (sample " +
                                  std::to_string(i) + ")");
}

// (1 / (t_N - t_0)) int g dt by the trapezoidal rule over the sample times.
template <typename G>
double time_average(std::span<const double> time, G g) {
  double integral = 0.0;
  for (std::size_t i = 1; i < time.size(); ++i)
    integral += 0.5 * (g(i - 1) + g(i)) * (time[i] - time[i - 1]);
  return integral / (time.back() - time.front());
}

double max_abs(std::span<const double> x) {
  double m = 0.0;
  for (const double v : x) m = std::max(m, std::abs(v));
  return m;
}

}  // namespace

double cumulative_error(std::span<const double> time, std::span<const double> ccm,
                        std::span<const double> rigid) {
  require_paired(ccm, rigid);
  require_times(time, ccm.size());
  // numerator of 2.34-2.36, as a time average
  const double mean_sq =
      time_average(time, [&](std::size_t i) { return (ccm[i] - rigid[i]) * (ccm[i] - rigid[i]); });
  const double mean_of_means = 0.5 * (time_average(time, [&](std::size_t i) { return ccm[i]; }) +
                                      time_average(time, [&](std::size_t i) { return rigid[i]; }));
  if (mean_sq == 0.0) return 0.0;
  if (mean_of_means == 0.0)
    throw std::domain_error("cumulative error: the two histories have zero combined mean");
  return mean_sq / mean_of_means;
}

double cumulative_error(std::span<const double> ccm, std::span<const double> rigid) {
  std::vector<double> index(ccm.size());
  std::iota(index.begin(), index.end(), 0.0);
  return cumulative_error(index, ccm, rigid);
}

double final_state_error(std::span<const double> ccm, std::span<const double> rigid) {
  require_paired(ccm, rigid);
  const double scale = std::max(max_abs(ccm), max_abs(rigid));  // denominator of 2.37-2.39
  if (scale == 0.0) return 0.0;
  return std::abs(ccm.back() - rigid.back()) / scale;
}

}  // namespace ccm::study
