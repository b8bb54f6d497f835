// Surface fits of every metric over (log10 ER, RLS), one per impactor kinetic energy level and
// per combination of the grid's other axes (thesis App. B: one surface per KE and metric; a
// grid with a `damping` axis gets one set of surfaces per damping level). Unusable points and
// the convergence runs (mesh_scale) are left out, visibly for the former.
#pragma once

#include <map>
#include <span>
#include <string>
#include <vector>

#include "records/point_metrics.hpp"
#include "study/fit/surface_fit.hpp"
#include "study/metrics/metric.hpp"

namespace ccm::study {

// The levels of a point's other axes (GridPoint::other_axes) that select its fits: every
// other axis except mesh_scale (the convergence runs, never fitted) and a template's coordinates
// (kTemplateAxisPrefix: they reach the fits through ER, RLS and KE). Empty on a grid that sweeps
// ER, RLS and KE only.
using AxisLevels = std::map<std::string, double>;
AxisLevels fit_axes(const GridPoint& point);
// "damping=1, penalty=0.1"; "" when empty.
std::string axes_text(const AxisLevels& axes);
// True for a convergence point (it carries other_axes["mesh_scale"]).
bool is_convergence_point(const GridPoint& point);

struct MetricFit {
  Metric metric = Metric::final_kinetic_energy;
  double kinetic_energy = 0.0;  // KE level [J]
  AxisLevels axes{};            // the other axes' levels of its points
  SurfaceFit fit;               // samples: x = log10 ER, y = RLS, id = grid point index
};

// A point left out of the fits, and why.
struct ExcludedPoint {
  int point_index = 0;
  double kinetic_energy = 0.0;
  std::string reason;
};

struct StudyFits {
  std::vector<MetricFit> fits;          // ordered by axes, KE, then metric
  std::vector<ExcludedPoint> excluded;  // unusable points (unstable runs, ...)
  std::vector<std::string> notes;       // (metric, KE, axes) that could not be fitted, and why

  // The fit of `metric` at exactly this KE level and these axes' levels, or nullptr.
  const MetricFit* find(Metric metric, double kinetic_energy, const AxisLevels& axes = {}) const;
  // The distinct KE levels that have fits at these axes' levels, ascending.
  std::vector<double> kinetic_energy_levels(const AxisLevels& axes = {}) const;
  // The distinct combinations of other-axis levels that have fits ({{}} on a plain grid).
  std::vector<AxisLevels> axis_groups() const;
};

// Fits every metric of kAllMetrics at every (KE, other axes) group of the usable points that
// are not convergence points.
StudyFits fit_study(std::span<const PointMetrics> points, const FitOptions& options = {});

}  // namespace ccm::study
