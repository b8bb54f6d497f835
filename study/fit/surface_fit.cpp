#include "study/fit/surface_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ccm::study {

double coefficient_of_determination(const PolynomialSurface& surface,
                                    std::span<const SurfaceSample> samples) {
  double mean = 0.0;
  for (const SurfaceSample& s : samples) mean += s.z;
  mean /= static_cast<double>(samples.size());
  double ss_res = 0.0, ss_tot = 0.0;
  for (const SurfaceSample& s : samples) {
    ss_res += std::pow(s.z - surface(s.x, s.y), 2);
    ss_tot += std::pow(s.z - mean, 2);
  }
  if (ss_tot == 0.0) return ss_res == 0.0 ? 1.0 : 0.0;
  return 1.0 - ss_res / ss_tot;
}

std::optional<double> leave_one_out_rmse(std::span<const SurfaceSample> samples,
                                         SurfaceDegree degree) {
  if (samples.size() < 2) return std::nullopt;
  std::vector<SurfaceSample> others(samples.begin() + 1, samples.end());
  double sum_sq = 0.0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    if (k > 0) others[k - 1] = samples[k - 1];  // others = all samples but k
    const auto surface = least_squares_surface(others, degree);
    if (!surface) return std::nullopt;
    sum_sq += std::pow(samples[k].z - (*surface)(samples[k].x, samples[k].y), 2);
  }
  return std::sqrt(sum_sq / static_cast<double>(samples.size()));
}

namespace {

struct Candidate {
  SurfaceDegree degree;
  double loo_rmse = 0.0;
};

std::vector<Candidate> qualifying_degrees(std::span<const SurfaceSample> samples,
                                          const FitOptions& options) {
  std::vector<Candidate> out;
  for (int p = 0; p <= options.max_degree_x; ++p)
    for (int q = 0; q <= options.max_degree_y; ++q) {
      const SurfaceDegree d{p, q};
      if (d.n_terms() >= static_cast<int>(samples.size())) continue;
      if (const auto loo = leave_one_out_rmse(samples, d)) out.push_back({d, *loo});
    }
  return out;
}

// The scale of the data for the tie tolerance: their range, or their size when they are all
// equal (then every degree fits them to rounding of that size).
double z_scale(std::span<const SurfaceSample> samples) {
  const auto [lo, hi] = std::minmax_element(samples.begin(), samples.end(),
                                            [](const auto& a, const auto& b) { return a.z < b.z; });
  return std::max({hi->z - lo->z, std::abs(lo->z), std::abs(hi->z)});
}

}  // namespace

std::optional<SurfaceFit> fit_surface(std::span<const SurfaceSample> samples,
                                      const FitOptions& options) {
  const std::vector<Candidate> candidates = qualifying_degrees(samples, options);
  if (candidates.empty()) return std::nullopt;
  double best = std::numeric_limits<double>::infinity();
  for (const Candidate& c : candidates) best = std::min(best, c.loo_rmse);
  const double tie = best + 1e-9 * z_scale(samples);
  const Candidate* chosen = nullptr;
  for (const Candidate& c : candidates)
    if (c.loo_rmse <= tie && (!chosen || c.degree.n_terms() < chosen->degree.n_terms()))
      chosen = &c;

  SurfaceFit fit;
  fit.surface = *least_squares_surface(samples, chosen->degree);  // full rank: LOO fits were
  fit.loo_rmse = chosen->loo_rmse;
  fit.r_squared = coefficient_of_determination(fit.surface, samples);
  fit.samples.assign(samples.begin(), samples.end());
  const auto [xl, xh] = std::minmax_element(samples.begin(), samples.end(),
                                            [](const auto& a, const auto& b) { return a.x < b.x; });
  const auto [yl, yh] = std::minmax_element(samples.begin(), samples.end(),
                                            [](const auto& a, const auto& b) { return a.y < b.y; });
  fit.x_min = xl->x;
  fit.x_max = xh->x;
  fit.y_min = yl->y;
  fit.y_max = yh->y;
  return fit;
}

}  // namespace ccm::study
