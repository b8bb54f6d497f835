#include "rig_models/calibrate/parameter_profile.hpp"

#include <algorithm>
#include <cmath>

namespace ccm::rig {
namespace {

constexpr double kOnBound = 1e-3;  // of the range

// Parameter i's three profile abscissae: inside the range, centred on the best when it lies a
// step from both bounds. The centre is not evaluated when it is the best.
struct ProfileLine {
  double centre = 0.0, h = 0.0;
  bool centre_is_best = true;
};

ProfileLine line_of(const SearchParameter& p, double best, const ProfileSettings& s) {
  ProfileLine l;
  l.h = s.step * (p.upper - p.lower);
  l.centre = std::clamp(best, p.lower + l.h, p.upper - l.h);
  l.centre_is_best = l.centre == best;
  return l;
}

std::vector<double> with(std::vector<double> x, size_t i, double value) {
  x[i] = value;
  return x;
}

ParameterSpread spread_of(const SearchParameter& p, double best, double best_objective,
                          const ProfileLine& l, std::optional<double> f_mid,
                          std::optional<double> f_lo, std::optional<double> f_hi,
                          const ProfileSettings& s) {
  ParameterSpread out;
  out.name = p.name;
  out.best = best;
  const double range = p.upper - p.lower;
  out.on_lower_bound = best - p.lower <= kOnBound * range;
  out.on_upper_bound = p.upper - best <= kOnBound * range;
  if (l.centre_is_best) f_mid = best_objective;
  if (!f_mid || !f_lo || !f_hi) return out;
  out.curvature =
      three_point_curvature(l.centre - l.h, *f_lo, l.centre, *f_mid, l.centre + l.h, *f_hi);
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
                                                const BatchObjective& objective,
                                                const ProfileSettings& settings) {
  // Every profile point of every parameter first, as one batch: per parameter the step below,
  // the step above and, when the best lies within a step of a bound, the shifted centre.
  std::vector<ProfileLine> lines;
  std::vector<std::vector<double>> points;
  for (size_t i = 0; i < parameters.size(); ++i) {
    const ProfileLine l = line_of(parameters[i], best[i], settings);
    lines.push_back(l);
    points.push_back(with(best, i, l.centre - l.h));
    points.push_back(with(best, i, l.centre + l.h));
    if (!l.centre_is_best) points.push_back(with(best, i, l.centre));
  }
  const std::vector<std::optional<double>> f = objective(points);
  std::vector<ParameterSpread> out;
  size_t k = 0;
  for (size_t i = 0; i < parameters.size(); ++i) {
    const ProfileLine& l = lines[i];
    const std::optional<double> f_lo = f.at(k), f_hi = f.at(k + 1);
    const std::optional<double> f_mid = l.centre_is_best ? std::nullopt : f.at(k + 2);
    k += l.centre_is_best ? 2 : 3;
    out.push_back(
        spread_of(parameters[i], best[i], best_objective, l, f_mid, f_lo, f_hi, settings));
  }
  return out;
}

std::vector<ParameterSpread> profile_parameters(const std::vector<SearchParameter>& parameters,
                                                const std::vector<double>& best,
                                                double best_objective,
                                                const SearchObjective& objective,
                                                const ProfileSettings& settings) {
  return profile_parameters(parameters, best, best_objective, one_at_a_time(objective), settings);
}

}  // namespace ccm::rig
