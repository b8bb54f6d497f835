#include "study/recommend/recommendation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

namespace ccm::study {

namespace {

void validate(const RecommendQuery& q) {
  if (!(q.modulus_ratio > 0.0) || !std::isfinite(q.modulus_ratio))
    throw std::invalid_argument("recommend: ER must be positive");
  if (!(q.kinetic_energy > 0.0) || !std::isfinite(q.kinetic_energy))
    throw std::invalid_argument("recommend: KE must be positive");
  if (!(q.length_ratio > 0.0) || !std::isfinite(q.length_ratio))
    throw std::invalid_argument("recommend: RLS must be positive");
  if (!(q.max_error >= 0.0) || !std::isfinite(q.max_error))
    throw std::invalid_argument("recommend: max error must be a non-negative number");
}

std::string levels_text(const std::set<double>& levels) {
  std::string out;
  for (double v : levels) out += fmt::format("{}{:g}", out.empty() ? "" : ", ", v);
  return out;
}

// The other axes' levels of the query's fits: given ones must be studied levels; an axis with
// one level may be left out.
AxisLevels resolve_axes(const StudyFits& fits, const AxisLevels& given) {
  std::map<std::string, std::set<double>> levels;
  for (const AxisLevels& group : fits.axis_groups())
    for (const auto& [name, value] : group) levels[name].insert(value);
  AxisLevels out;
  for (const auto& [name, value] : given) {
    const auto it = levels.find(name);
    if (it == levels.end())
      throw std::invalid_argument(
          fmt::format("recommend: --axis {}: the study has no such axis{}", name,
                      levels.empty() ? " (it sweeps ER, RLS and KE only)" : ""));
    if (!it->second.contains(value))
      throw std::invalid_argument(fmt::format(
          "recommend: --axis {}={:g}: not a studied level of {} (levels: {}); the fits do not "
          "interpolate across other axes",
          name, value, name, levels_text(it->second)));
    out[name] = value;
  }
  for (const auto& [name, values] : levels) {
    if (out.contains(name)) continue;
    if (values.size() > 1)
      throw std::invalid_argument(
          fmt::format("recommend: the study has {} levels of axis '{}' ({}): choose one with "
                      "--axis {}=VALUE",
                      values.size(), name, levels_text(values), name));
    out[name] = *values.begin();
  }
  return out;
}

// The studied KE levels bracketing the query, with the linear weight of the upper one.
struct KeBracket {
  double low = 0.0, high = 0.0, weight_high = 0.0;
};

KeBracket bracket(const std::vector<double>& levels, double ke, std::vector<std::string>& warn) {
  if (levels.empty()) throw std::runtime_error("recommend: the study has no fits");
  if (ke <= levels.front() || ke >= levels.back()) {
    const double nearest = ke <= levels.front() ? levels.front() : levels.back();
    if (ke != nearest)
      warn.push_back(
          fmt::format("KE = {} J lies outside the studied levels [{}, {}] J; the "
                      "surfaces at {} J are used unchanged",
                      ke, levels.front(), levels.back(), nearest));
    return {nearest, nearest, 0.0};
  }
  const auto upper = std::upper_bound(levels.begin(), levels.end(), ke);
  const double lo = *(upper - 1), hi = *upper;
  return {lo, hi, (ke - lo) / (hi - lo)};
}

// One fitted quantity at the query: the surface clamped to the range its samples span,
// interpolated linearly in KE; its uncertainty is the larger leave-one-out RMSE of the two.
struct MetricPrediction {
  double value = 0.0;
  double loo_rmse = 0.0;
};

struct Predictor {
  const StudyFits& fits;
  const AxisLevels& axes;
  KeBracket ke;
  double x = 0.0, y = 0.0;
  std::vector<std::string>& clamped;

  double at_level(Metric metric, double level, double& loo) const {
    const MetricFit* f = fits.find(metric, level, axes);
    if (!f)
      throw std::runtime_error(fmt::format("recommend: no fit of {} at KE = {} J{}{}",
                                           to_string(metric), level, axes.empty() ? "" : ", ",
                                           axes_text(axes)));
    const auto [lo, hi] = std::minmax_element(
        f->fit.samples.begin(), f->fit.samples.end(),
        [](const SurfaceSample& a, const SurfaceSample& b) { return a.z < b.z; });
    // Above the studied ER the impactor is rigid for every practical purpose: the rigid model's
    // errors are those at the highest studied ER (docs/recommendation.md, "Toward the rigid
    // limit"); the cost ratio keeps growing with the impactor's own step.
    const double xe = metric == Metric::log10_runtime_ratio ? x : std::min(x, f->fit.x_max);
    const double raw = f->fit.surface(xe, y);
    loo = std::max(loo, f->fit.loo_rmse);
    if (f->fit.samples.empty()) return raw;
    // An error is never negative (the measured minimum may be -1e-17 of rounding).
    const double floor = fitted_in_log10(metric) ? lo->z : std::max(lo->z, 0.0);
    const double value = std::clamp(raw, floor, std::max(floor, hi->z));
    if (value != raw)
      clamped.push_back(
          fmt::format("{} at KE {:g} J: the surface gives {:.3g}, outside the range measured there "
                      "[{:.3g}, {:.3g}]; clamped to {:.3g}",
                      to_string(metric), level, raw, floor, hi->z, value));
    return value;
  }

  MetricPrediction operator()(Metric metric) const {
    MetricPrediction p;
    const double low = at_level(metric, ke.low, p.loo_rmse);
    p.value = ke.weight_high == 0.0 ? low
                                    : (1.0 - ke.weight_high) * low +
                                          ke.weight_high * at_level(metric, ke.high, p.loo_rmse);
    return p;
  }
};

void warn_outside_grid(const StudyFits& fits, const AxisLevels& axes,
                       const std::vector<double>& levels, double x, double y,
                       std::vector<std::string>& warn) {
  for (const double ke : levels) {
    const MetricFit* f = fits.find(Metric::log10_runtime_ratio, ke, axes);
    if (!f) continue;
    const SurfaceFit& s = f->fit;
    if (x < s.x_min)
      warn.push_back(
          fmt::format("log10 ER = {:.3g} lies outside the studied [{:.3g}, {:.3g}] at "
                      "KE = {} J: the surfaces are extrapolated",
                      x, s.x_min, s.x_max, ke));
    if (x > s.x_max)
      warn.push_back(fmt::format(
          "log10 ER = {:.3g} lies above the studied [{:.3g}, {:.3g}] at KE = {} J: the rigid "
          "model's errors are those at the highest ER (the rigid limit), the cost ratio is "
          "extrapolated",
          x, s.x_min, s.x_max, ke));
    if (y < s.y_min || y > s.y_max)
      warn.push_back(
          fmt::format("RLS = {:.3g} lies outside the studied [{:.3g}, {:.3g}] at "
                      "KE = {} J: the surfaces are extrapolated",
                      y, s.y_min, s.y_max, ke));
  }
}

Prediction predict(const Predictor& p) {
  Prediction out;
  const MetricPrediction um = p(Metric::final_u_mean), ux = p(Metric::final_u_max),
                         ke = p(Metric::final_kinetic_energy), rtr = p(Metric::log10_runtime_ratio);
  out.final_state = {um.value, ux.value, ke.value};
  out.runtime_ratio = std::pow(10.0, rtr.value);
  out.uncertainty = {{um.loo_rmse, ux.loo_rmse, ke.loo_rmse}, rtr.loo_rmse};
  out.weighting = {std::pow(10.0, p(Metric::log10_w_u_mean).value),
                   std::pow(10.0, p(Metric::log10_w_u_max).value),
                   std::pow(10.0, p(Metric::log10_w_kinetic_energy).value)};
  return out;
}

bool usable_grid_point(const PointMetrics& m) { return m.usable && !is_convergence_point(m.point); }

// Spacing of the distinct levels of one coordinate ((max - min) / (n - 1)); 1 for one level.
double spacing(std::set<double> levels) {
  if (levels.size() < 2) return 1.0;
  return (*levels.rbegin() - *levels.begin()) / static_cast<double>(levels.size() - 1);
}

std::vector<NearbyPoint> nearest_points(std::span<const PointMetrics> measured,
                                        const AxisLevels& axes, const RecommendQuery& q,
                                        double max_error) {
  std::vector<const PointMetrics*> group;
  std::set<double> xs, ys, ks;
  for (const PointMetrics& m : measured)
    if (usable_grid_point(m) && fit_axes(m.point) == axes) {
      group.push_back(&m);
      xs.insert(std::log10(m.point.modulus_ratio));
      ys.insert(m.point.length_ratio);
      ks.insert(m.point.kinetic_energy);
    }
  const double dx = spacing(xs), dy = spacing(ys), dk = spacing(ks);
  std::vector<NearbyPoint> out;
  for (const PointMetrics* m : group) {
    const double d = std::hypot((std::log10(m->point.modulus_ratio / q.modulus_ratio)) / dx,
                                (m->point.length_ratio - q.length_ratio) / dy,
                                (m->point.kinetic_energy - q.kinetic_energy) / dk);
    const DecisionInputs in = measured_inputs(*m);
    out.push_back({m->point, d, in, m->weighting, decide_model(in, max_error), m->impact_errors});
  }
  std::stable_sort(out.begin(), out.end(), [](const NearbyPoint& a, const NearbyPoint& b) {
    return a.distance < b.distance;
  });
  if (out.size() > static_cast<std::size_t>(kNearestPoints)) out.resize(kNearestPoints);
  return out;
}

// A query this close to a grid point (in grid spacings) is that point: the grid's levels are
// typed by hand or printed with %g, so 1e-6 of a spacing separates rounding from a new point.
constexpr double kSamePointDistance = 1e-6;

void compare_with_measured(Recommendation& r) {
  if (r.nearest.empty() || r.nearest.front().distance > kSamePointDistance) return;
  r.at_grid_point = true;
  const NearbyPoint& p = r.nearest.front();
  if (p.decision.model == r.model) return;
  r.measured_disagrees = true;
  r.reliability.reliable = false;
  r.reliability.reasons.push_back(fmt::format(
      "this is grid point {}, whose measured values give {} (errors u_mean {:.3g}, u_max {:.3g}, "
      "KE {:.3g}; RTR {:.3g}): the fitted surfaces do not reproduce it",
      p.point.index, to_string(p.decision.model), p.measured.final_state.u_mean,
      p.measured.final_state.u_max, p.measured.final_state.kinetic_energy,
      p.measured.runtime_ratio));
}

// ER, RLS and KE of the query against their ranges over the usable points at these levels.
std::vector<GroupRange> group_ranges(std::span<const PointMetrics> measured, const AxisLevels& axes,
                                     const RecommendQuery& q) {
  std::vector<GroupRange> g = {
      {"ER", "", q.modulus_ratio, std::numeric_limits<double>::infinity(),
       -std::numeric_limits<double>::infinity()},
      {"RLS", "", q.length_ratio, std::numeric_limits<double>::infinity(),
       -std::numeric_limits<double>::infinity()},
      {"KE", "J", q.kinetic_energy, std::numeric_limits<double>::infinity(),
       -std::numeric_limits<double>::infinity()}};
  for (const PointMetrics& m : measured) {
    if (!usable_grid_point(m) || fit_axes(m.point) != axes) continue;
    const double v[3] = {m.point.modulus_ratio, m.point.length_ratio, m.point.kinetic_energy};
    for (std::size_t k = 0; k < 3; ++k) {
      g[k].low = std::min(g[k].low, v[k]);
      g[k].high = std::max(g[k].high, v[k]);
    }
  }
  return g;
}

}  // namespace

std::string GroupRange::text() const {
  const std::string u = unit.empty() ? "" : " " + unit;
  return fmt::format("{} {:g}{} ({} the studied {:g} to {:g}{})", name, value, u,
                     inside() ? "inside" : "OUTSIDE", low, high, u);
}

DecisionInputs measured_inputs(const PointMetrics& point) {
  return {point.final_state, point.runtime_ratio};
}

Recommendation recommend(const StudyFits& fits, std::span<const PointMetrics> measured,
                         const RecommendQuery& query) {
  validate(query);
  Recommendation r;
  r.axes = resolve_axes(fits, query.axes);
  const KeBracket b = bracket(fits.kinetic_energy_levels(r.axes), query.kinetic_energy, r.warnings);
  r.kinetic_energy_levels_used = b.low == b.high ? std::vector{b.low} : std::vector{b.low, b.high};
  const double x = std::log10(query.modulus_ratio), y = query.length_ratio;
  warn_outside_grid(fits, r.axes, r.kinetic_energy_levels_used, x, y, r.warnings);
  r.predicted = predict(Predictor{fits, r.axes, b, x, y, r.clamped});
  const DecisionInputs inputs{r.predicted.final_state, r.predicted.runtime_ratio};
  r.decision = decide_model(inputs, query.max_error);
  r.model = r.decision.model;
  r.rule = decision_rule_text(query.max_error);
  r.reason = decision_reason(inputs, r.decision, query.max_error);
  r.reliability = decision_reliability(inputs, r.predicted.uncertainty, query.max_error);
  r.nearest = nearest_points(measured, r.axes, query, query.max_error);
  r.groups = group_ranges(measured, r.axes, query);
  compare_with_measured(r);
  return r;
}

std::vector<PointDecision> decide_grid_points(const StudyFits& fits,
                                              std::span<const PointMetrics> measured,
                                              double max_error) {
  std::vector<PointDecision> out;
  for (const PointMetrics& m : measured) {
    if (!usable_grid_point(m)) continue;
    PointDecision d{&m, decide_model(measured_inputs(m), max_error), std::nullopt};
    if (fits.find(Metric::log10_runtime_ratio, m.point.kinetic_energy, fit_axes(m.point))) {
      RecommendQuery q{m.point.modulus_ratio, m.point.length_ratio, m.point.kinetic_energy,
                       fit_axes(m.point), max_error};
      try {
        d.fitted = recommend(fits, measured, q);
      } catch (const std::runtime_error&) {  // a metric the rule needs has no fit here
        d.fitted.reset();
      }
    }
    out.push_back(std::move(d));
  }
  return out;
}

}  // namespace ccm::study
