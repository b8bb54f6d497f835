#include "study/metrics/model_errors.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace ccm::study {

namespace {

void require_paired(std::span<const double> ccm, std::span<const double> rigid) {
  if (ccm.empty() || ccm.size() != rigid.size())
    throw std::invalid_argument("model errors need two non-empty histories of equal length (ccm " +
                                std::to_string(ccm.size()) + ", rigid " +
                                std::to_string(rigid.size()) + " samples)");
}

double mean(std::span<const double> x) {
  return std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size());
}

double max_abs(std::span<const double> x) {
  double m = 0.0;
  for (const double v : x) m = std::max(m, std::abs(v));
  return m;
}

}  // namespace

double cumulative_error(std::span<const double> ccm, std::span<const double> rigid) {
  require_paired(ccm, rigid);
  double sum_sq = 0.0;  // numerator of 2.34-2.36
  for (std::size_t i = 0; i < ccm.size(); ++i) sum_sq += (ccm[i] - rigid[i]) * (ccm[i] - rigid[i]);
  const double mean_of_means = 0.5 * (mean(ccm) + mean(rigid));
  if (sum_sq == 0.0) return 0.0;
  if (mean_of_means == 0.0)
    throw std::domain_error("cumulative error: the two histories have zero combined mean");
  return sum_sq / mean_of_means;
}

double final_state_error(std::span<const double> ccm, std::span<const double> rigid) {
  require_paired(ccm, rigid);
  const double scale = std::max(max_abs(ccm), max_abs(rigid));  // denominator of 2.37-2.39
  if (scale == 0.0) return 0.0;
  return std::abs(ccm.back() - rigid.back()) / scale;
}

}  // namespace ccm::study
