// Surface fits of every metric over (log10 ER, RLS), one per impactor kinetic energy level
// (thesis App. B: one surface per KE and metric). Unusable points are left out, visibly.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "study/fit/surface_fit.hpp"
#include "study/metrics/metric.hpp"
#include "study/metrics/point_metrics.hpp"

namespace ccm::study {

struct MetricFit {
  Metric metric = Metric::w_kinetic_energy;
  double kinetic_energy = 0.0;  // KE level [J]
  SurfaceFit fit;               // samples: x = log10 ER, y = RLS, id = grid point index
};

// A point left out of the fits, and why.
struct ExcludedPoint {
  int point_index = 0;
  double kinetic_energy = 0.0;
  std::string reason;
};

struct StudyFits {
  std::vector<MetricFit> fits;          // ordered by KE, then metric
  std::vector<ExcludedPoint> excluded;  // unusable points (unstable runs, ...)
  std::vector<std::string> notes;       // (metric, KE) pairs that could not be fitted, and why

  // The fit of `metric` at exactly this KE level, or nullptr.
  const MetricFit* find(Metric metric, double kinetic_energy) const;
  // The distinct KE levels that have fits, ascending.
  std::vector<double> kinetic_energy_levels() const;
};

// Fits every metric of kAllMetrics at every KE level of the usable points.
StudyFits fit_study(std::span<const PointMetrics> points, const FitOptions& options = {});

}  // namespace ccm::study
