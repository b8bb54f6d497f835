#include "study/fit/study_fits.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "study/grid/grid_spec.hpp"

namespace ccm::study {

AxisLevels fit_axes(const GridPoint& point) {
  AxisLevels axes = point.other_axes;
  axes.erase("mesh_scale");
  std::erase_if(axes, [](const auto& axis) { return axis.first.starts_with(kTemplateAxisPrefix); });
  return axes;
}

std::string axes_text(const AxisLevels& axes) {
  std::string out;
  for (const auto& [name, value] : axes)
    out += fmt::format("{}{}={:g}", out.empty() ? "" : ", ", name, value);
  return out;
}

bool is_convergence_point(const GridPoint& point) {
  return point.other_axes.contains("mesh_scale");
}

const MetricFit* StudyFits::find(Metric metric, double kinetic_energy,
                                 const AxisLevels& axes) const {
  for (const MetricFit& f : fits)
    if (f.metric == metric && f.kinetic_energy == kinetic_energy && f.axes == axes) return &f;
  return nullptr;
}

std::vector<double> StudyFits::kinetic_energy_levels(const AxisLevels& axes) const {
  std::set<double> levels;
  for (const MetricFit& f : fits)
    if (f.axes == axes) levels.insert(f.kinetic_energy);
  return {levels.begin(), levels.end()};
}

std::vector<AxisLevels> StudyFits::axis_groups() const {
  std::set<AxisLevels> groups;
  for (const MetricFit& f : fits) groups.insert(f.axes);
  return {groups.begin(), groups.end()};
}

namespace {

using Group = std::pair<AxisLevels, double>;  // other axes' levels, KE

std::vector<SurfaceSample> samples_of(std::span<const PointMetrics> points, Metric metric,
                                      const Group& group) {
  std::vector<SurfaceSample> samples;
  for (const PointMetrics& p : points)
    if (p.usable && !is_convergence_point(p.point) && p.point.kinetic_energy == group.second &&
        fit_axes(p.point) == group.first)
      samples.push_back({std::log10(p.point.modulus_ratio), p.point.length_ratio,
                         metric_value(p, metric), p.point.index});
  return samples;
}

}  // namespace

StudyFits fit_study(std::span<const PointMetrics> points, const FitOptions& options) {
  StudyFits out;
  std::set<Group> groups;
  for (const PointMetrics& p : points) {
    if (is_convergence_point(p.point)) continue;
    if (p.usable)
      groups.insert({fit_axes(p.point), p.point.kinetic_energy});
    else
      out.excluded.push_back({p.point.index, p.point.kinetic_energy, p.excluded_reason});
  }
  for (const Group& group : groups)
    for (const Metric metric : kAllMetrics) {
      const std::vector<SurfaceSample> samples = samples_of(points, metric, group);
      if (auto fit = fit_surface(samples, options))
        out.fits.push_back({metric, group.second, group.first, std::move(*fit)});
      else
        out.notes.push_back(fmt::format(
            "{} at KE = {} J{}{}: {} usable point(s), too few for a fit", to_string(metric),
            group.second, group.first.empty() ? "" : ", ", axes_text(group.first), samples.size()));
    }
  return out;
}

}  // namespace ccm::study
