#include "rig_models/calibrate/parameter_profile.hpp"

#include <algorithm>
#include <cmath>

namespace ccm::rig {
namespace {

constexpr double kOnBound = 1e-3;  // of the range

// The objective with parameter i at `value`, the others at `best`.
std::optional<double> along(const SearchObjective& objective, std::vector<double> x, size_t i,
                            double value) {
  x[i] = value;
  return objective(x);
}

ParameterSpread profile_one(const SearchParameter& p, size_t i, const std::vector<double>& best,
                            double best_objective, const SearchObjective& objective,
                            const ProfileSettings& s) {
  ParameterSpread out;
  out.name = p.name;
  out.best = best[i];
  const double range = p.upper - p.lower, h = s.step * range;
  out.on_lower_bound = best[i] - p.lower <= kOnBound * range;
  out.on_upper_bound = p.upper - best[i] <= kOnBound * range;
  // Three points inside the range, centred on the best when it lies a step from both bounds.
  const double centre = std::clamp(best[i], p.lower + h, p.upper - h);
  const std::optional<double> f_mid =
      centre == best[i] ? std::optional<double>(best_objective) : along(objective, best, i, centre);
  const std::optional<double> f_lo = along(objective, best, i, centre - h);
  const std::optional<double> f_hi = along(objective, best, i, centre + h);
  if (!f_mid || !f_lo || !f_hi) return out;
  out.curvature = three_point_curvature(centre - h, *f_lo, centre, *f_mid, centre + h, *f_hi);
  if (*out.curvature > 0.0)
    out.half_width = std::sqrt(2.0 * s.rise * best_objective / *out.curvature);
  return out;
}

}  // namespace

double three_point_curvature(double x0, double f0, double x1, double f1, double x2, double f2) {
  const double h_lo = x1 - x0, h_hi = x2 - x1;
  return 2.0 * ((f2 - f1) / h_hi - (f1 - f0) / h_lo) / (h_lo + h_hi);
}

std::vector<ParameterSpread> profile_parameters(const std::vector<SearchParameter>& parameters,
                                                const std::vector<double>& best,
                                                double best_objective,
                                                const SearchObjective& objective,
                                                const ProfileSettings& settings) {
  std::vector<ParameterSpread> out;
  for (size_t i = 0; i < parameters.size(); ++i)
    out.push_back(profile_one(parameters[i], i, best, best_objective, objective, settings));
  return out;
}

}  // namespace ccm::rig
