// Which impactor model to use at a design point, and why (thesis 2.8, Fig. 2-29, App. B):
// the fitted surfaces predict the final-state errors of the rigid model against CCM, the
// runtime ratio and the weighting functions w = error / RTR at (log10 ER, RLS), interpolated
// linearly in KE between the two nearest studied levels.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "study/fit/study_fits.hpp"
#include "study/grid/grid_point.hpp"
#include "study/metrics/point_metrics.hpp"

namespace ccm::study {

struct RecommendQuery {
  double modulus_ratio = 1.0;   // ER = E_I / E_A (eq. 2.32)
  double length_ratio = 1.0;    // RLS = D_I / L_A (eq. 2.33)
  double kinetic_energy = 0.0;  // KE_I [J]
  // When set, the decision is by error alone: rigid when all three predicted final-state
  // errors are below it, CCM otherwise.
  std::optional<double> max_error;
  // Without max_error, the decision is by the weighting functions: CCM when the largest
  // predicted w reaches this value. 0.1 (10 % error per unit runtime ratio) is the thesis's
  // reading of Fig. 4-1, where a weight "sub 10 %" marked CCM as less recommended.
  double w_threshold = 0.1;
};

struct Prediction {
  ArtifactErrors final_state;  // eqs. 2.37-2.39
  double runtime_ratio = 0.0;  // RTR (eq. 2.40)
  ArtifactErrors weighting;    // w, from their own fitted surfaces
};

struct Recommendation {
  ImpactModel model = ImpactModel::ccm;
  std::string reason;  // one sentence with the deciding numbers
  Prediction predicted;
  std::vector<double> kinetic_energy_levels_used;  // one or two studied KE levels
  std::vector<std::string> warnings;  // extrapolation outside the studied grid, clamped KE, ...
};

// Throws std::invalid_argument on a non-positive ER or KE or a negative threshold, and
// std::runtime_error when the fits lack a needed metric at a needed KE level.
Recommendation recommend(const StudyFits& fits, const RecommendQuery& query);

}  // namespace ccm::study
