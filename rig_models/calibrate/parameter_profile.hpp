// How well a calibration pins each parameter down: the objective's curvature along each
// parameter at the best point, from a three-point profile (the best and a step h either side,
// or three points a step apart inside the range when the best lies within h of a bound), and the
// half-width over which the objective rises by a given fraction of its best value:
//
//   f'' = 2 [ (f+ - f0) / h+ - (f0 - f-) / h- ] / (h+ + h-)      (three points, any spacing)
//   half_width = sqrt(2 rise f* / f'')                            (a parabola's rise by rise f*)
//
// This is a sensitivity, not a confidence interval: the objective is a mean nRMSE, not a
// likelihood. A parameter whose objective does not rise (f'' <= 0) is reported unidentified, and
// one that ends within 1e-3 of its range from a bound is flagged: its best may lie beyond.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "rig_models/calibrate/bounded_search.hpp"

namespace ccm::rig {

struct ParameterSpread {
  std::string name;
  double best = 0.0;
  std::optional<double> curvature;   // f'' along the parameter; none when an evaluation failed
  std::optional<double> half_width;  // where the objective rises by `rise` f*; none if f'' <= 0
  bool on_lower_bound = false, on_upper_bound = false;
};

struct ProfileSettings {
  double step = 0.1;   // h as a fraction of each range
  double rise = 0.05;  // the objective's relative rise that defines the half-width
};

// Evaluates `objective` at 2 or 3 points per parameter (the others held at `best`), all of them
// in one batch.
std::vector<ParameterSpread> profile_parameters(const std::vector<SearchParameter>& parameters,
                                                const std::vector<double>& best,
                                                double best_objective,
                                                const BatchObjective& objective,
                                                const ProfileSettings& settings = {});
std::vector<ParameterSpread> profile_parameters(const std::vector<SearchParameter>& parameters,
                                                const std::vector<double>& best,
                                                double best_objective,
                                                const SearchObjective& objective,
                                                const ProfileSettings& settings = {});

// f'' from three points (x_i, f_i), x0 < x1 < x2.
double three_point_curvature(double x0, double f0, double x1, double f1, double x2, double f2);

}  // namespace ccm::rig
