// Which impactor model to use at a design point, and why (thesis 2.8, Fig. 2-29, App. B; the
// rule is study/recommend/decision_rule.hpp, docs/recommendation.md). The fitted surfaces of
// the point's axis group predict the rigid model's final-state errors against CCM, log10 RTR
// and log10 w at (log10 ER, RLS); each prediction is clamped to the range measured at its KE
// level and interpolated linearly in KE between the two nearest studied levels. The answer
// says whether it can be trusted (the fits' leave-one-out error against the decision's margin,
// and the measured answer when the query is a grid point) and names the nearest measured points.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "records/grid_point.hpp"
#include "records/point_metrics.hpp"
#include "study/fit/study_fits.hpp"
#include "study/recommend/decision_rule.hpp"

namespace ccm::study {

struct RecommendQuery {
  double modulus_ratio = 1.0;   // ER = E_I / E_A (eq. 2.32)
  double length_ratio = 1.0;    // RLS = D_I / L_A (eq. 2.33)
  double kinetic_energy = 0.0;  // KE_I [J]
  // Levels of the grid's other axes (`--axis name=value`); an axis with one level may be left
  // out, one with several levels must be given.
  AxisLevels axes{};
  double max_error = kDefaultMaxError;
};

struct Prediction {
  ArtifactErrors final_state;       // eqs. 2.37-2.39, clamped to the measured range
  double runtime_ratio = 1.0;       // RTR = 10^(fitted log10 RTR), clamped likewise
  ArtifactErrors weighting;         // w = 10^(fitted log10 w), informational
  DecisionUncertainty uncertainty;  // leave-one-out RMSE of the errors' and log10 RTR's fits
};

// A measured grid point near the query, with its measured answer.
struct NearbyPoint {
  GridPoint point;
  double distance = 0.0;  // in grid spacings of (log10 ER, RLS, KE)
  DecisionInputs measured;
  ArtifactErrors weighting;
  Decision decision;
  // The designer's errors of its whole runs (docs/metrics.md), when its runs kept them.
  std::optional<ImpactErrors> impact_errors;
};

inline constexpr int kNearestPoints = 3;

// One group of the design point against the range the study measured it over (its usable grid
// points at the answer's axis levels): a prediction outside says so.
struct GroupRange {
  std::string name;  // "ER", "RLS", "KE"
  std::string unit;  // "" or "J"
  double value = 0.0, low = 0.0, high = 0.0;
  bool inside() const { return value >= low && value <= high; }
  // "ER 30 (inside the studied 1 to 100)", "RLS 0.2 (OUTSIDE the studied 0.5 to 1.5)"
  std::string text() const;
};

struct Recommendation {
  ImpactModel model = ImpactModel::ccm;
  Decision decision;
  std::string rule;    // decision_rule_text(max_error)
  std::string reason;  // decision_reason on the predicted values
  Prediction predicted;
  AxisLevels axes;                                 // the other axes' levels used
  std::vector<double> kinetic_energy_levels_used;  // one or two studied KE levels
  // False when the fits' leave-one-out error exceeds the decision margin, or when the query is
  // a grid point whose measured values give the other model; `reliability.reasons` says why.
  Reliability reliability;
  bool at_grid_point = false;         // the query is a measured grid point
  bool measured_disagrees = false;    // ... and its measured values give the other model
  std::vector<NearbyPoint> nearest;   // the kNearestPoints nearest measured points, nearest first
  std::vector<std::string> clamped;   // predictions moved into the measured range, and how
  std::vector<std::string> warnings;  // extrapolation outside the studied grid, clamped KE, ...
  std::vector<GroupRange> groups;     // ER, RLS, KE against the studied ranges
};

// `measured`: the study's grid points (the fits' samples); convergence and unusable points are
// skipped. Throws std::invalid_argument on a non-positive ER or KE, a negative or non-finite
// max error, an unknown axis or level, or a missing level of an axis that has several; and
// std::runtime_error when the fits lack a needed metric at a needed KE level.
Recommendation recommend(const StudyFits& fits, std::span<const PointMetrics> measured,
                         const RecommendQuery& query);

// The rule at one grid point, on its measured values and on the fitted surfaces.
struct PointDecision {
  const PointMetrics* point = nullptr;
  Decision measured;
  // Empty when the point's group lacks a fit the rule needs (too few usable points).
  std::optional<Recommendation> fitted;
  // The fitted answer differs from the measured one, or it is unreliable.
  bool flagged() const { return fitted && !fitted->reliability.reliable; }
};

// Every usable, non-convergence point of `measured`, in order.
std::vector<PointDecision> decide_grid_points(const StudyFits& fits,
                                              std::span<const PointMetrics> measured,
                                              double max_error);

// The measured inputs of the rule at a usable point.
DecisionInputs measured_inputs(const PointMetrics& point);

}  // namespace ccm::study
