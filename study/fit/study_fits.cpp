#include "study/fit/study_fits.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace ccm::study {

const MetricFit* StudyFits::find(Metric metric, double kinetic_energy) const {
  for (const MetricFit& f : fits)
    if (f.metric == metric && f.kinetic_energy == kinetic_energy) return &f;
  return nullptr;
}

std::vector<double> StudyFits::kinetic_energy_levels() const {
  std::set<double> levels;
  for (const MetricFit& f : fits) levels.insert(f.kinetic_energy);
  return {levels.begin(), levels.end()};
}

namespace {

std::vector<SurfaceSample> samples_of(std::span<const PointMetrics> points, Metric metric,
                                      double kinetic_energy) {
  std::vector<SurfaceSample> samples;
  for (const PointMetrics& p : points)
    if (p.usable && p.point.kinetic_energy == kinetic_energy)
      samples.push_back({std::log10(p.point.modulus_ratio), p.point.length_ratio,
                         metric_value(p, metric), p.point.index});
  return samples;
}

}  // namespace

StudyFits fit_study(std::span<const PointMetrics> points, const FitOptions& options) {
  StudyFits out;
  std::set<double> levels;
  for (const PointMetrics& p : points) {
    if (p.usable)
      levels.insert(p.point.kinetic_energy);
    else
      out.excluded.push_back({p.point.index, p.point.kinetic_energy, p.excluded_reason});
  }
  for (const double ke : levels)
    for (const Metric metric : kAllMetrics) {
      const std::vector<SurfaceSample> samples = samples_of(points, metric, ke);
      if (auto fit = fit_surface(samples, options))
        out.fits.push_back({metric, ke, std::move(*fit)});
      else
        out.notes.push_back(fmt::format("{} at KE = {} J: {} usable point(s), too few for a fit",
                                        to_string(metric), ke, samples.size()));
    }
  return out;
}

}  // namespace ccm::study
