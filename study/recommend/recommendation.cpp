#include "study/recommend/recommendation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ccm::study {

namespace {

void validate(const RecommendQuery& q) {
  if (!(q.modulus_ratio > 0.0)) throw std::invalid_argument("recommend: ER must be positive");
  if (!(q.kinetic_energy > 0.0)) throw std::invalid_argument("recommend: KE must be positive");
  if (q.max_error && !(*q.max_error >= 0.0))
    throw std::invalid_argument("recommend: max error must be non-negative");
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

double predict(const StudyFits& fits, Metric metric, const KeBracket& b, double x, double y) {
  auto at = [&](double ke) {
    const MetricFit* f = fits.find(metric, ke);
    if (!f)
      throw std::runtime_error(
          fmt::format("recommend: no fit of {} at KE = {} J", to_string(metric), ke));
    return f->fit.surface(x, y);
  };
  const double low = at(b.low);
  return b.weight_high == 0.0 ? low : (1.0 - b.weight_high) * low + b.weight_high * at(b.high);
}

void warn_outside_grid(const StudyFits& fits, const std::vector<double>& levels, double x, double y,
                       std::vector<std::string>& warn) {
  for (const double ke : levels) {
    const MetricFit* f = fits.find(Metric::runtime_ratio, ke);
    if (!f) continue;
    const SurfaceFit& s = f->fit;
    if (x < s.x_min || x > s.x_max)
      warn.push_back(
          fmt::format("log10 ER = {:.3g} lies outside the studied [{:.3g}, {:.3g}] at "
                      "KE = {} J: the surfaces are extrapolated",
                      x, s.x_min, s.x_max, ke));
    if (y < s.y_min || y > s.y_max)
      warn.push_back(
          fmt::format("RLS = {:.3g} lies outside the studied [{:.3g}, {:.3g}] at "
                      "KE = {} J: the surfaces are extrapolated",
                      y, s.y_min, s.y_max, ke));
  }
}

// Polynomial surfaces can leave the physical range, mostly when extrapolated.
void warn_unphysical(const Prediction& p, std::vector<std::string>& warn) {
  const ArtifactErrors& e = p.final_state;
  if (std::min({e.u_mean, e.u_max, e.kinetic_energy}) < 0.0)
    warn.push_back(
        "a predicted final-state error is negative: the fitted surface is outside "
        "its physical range here; treat the prediction as unreliable");
  if (!(p.runtime_ratio > 0.0))
    warn.push_back(
        fmt::format("the predicted runtime ratio {:.3g} is not positive: the fitted "
                    "surface is outside its physical range here",
                    p.runtime_ratio));
}

void decide(const RecommendQuery& q, Recommendation& r) {
  const ArtifactErrors& e = r.predicted.final_state;
  const ArtifactErrors& w = r.predicted.weighting;
  if (q.max_error) {
    const double worst = std::max({e.u_mean, e.u_max, e.kinetic_energy});
    r.model = worst < *q.max_error ? ImpactModel::rigid : ImpactModel::ccm;
    r.reason = fmt::format(
        "predicted final-state errors of the rigid model (u_mean {:.3g}, u_max {:.3g}, KE {:.3g}) "
        "are {} the maximum error {:.3g}; CCM costs {:.3g}x the rigid runtime (RTR)",
        e.u_mean, e.u_max, e.kinetic_energy, worst < *q.max_error ? "all below" : "not all below",
        *q.max_error, r.predicted.runtime_ratio);
    return;
  }
  const double w_max = std::max({w.u_mean, w.u_max, w.kinetic_energy});
  r.model = w_max >= q.w_threshold ? ImpactModel::ccm : ImpactModel::rigid;
  r.reason = fmt::format(
      "largest predicted weighting function w = error / RTR is {:.3g} (u_mean {:.3g}, u_max "
      "{:.3g}, KE {:.3g}), {} the threshold {:.3g}; predicted RTR {:.3g}",
      w_max, w.u_mean, w.u_max, w.kinetic_energy, w_max >= q.w_threshold ? "at or above" : "below",
      q.w_threshold, r.predicted.runtime_ratio);
}

}  // namespace

Recommendation recommend(const StudyFits& fits, const RecommendQuery& query) {
  validate(query);
  Recommendation r;
  const KeBracket b = bracket(fits.kinetic_energy_levels(), query.kinetic_energy, r.warnings);
  r.kinetic_energy_levels_used = b.low == b.high ? std::vector{b.low} : std::vector{b.low, b.high};
  const double x = std::log10(query.modulus_ratio), y = query.length_ratio;
  warn_outside_grid(fits, r.kinetic_energy_levels_used, x, y, r.warnings);
  auto p = [&](Metric m) { return predict(fits, m, b, x, y); };
  r.predicted.final_state = {p(Metric::final_u_mean), p(Metric::final_u_max),
                             p(Metric::final_kinetic_energy)};
  r.predicted.runtime_ratio = p(Metric::runtime_ratio);
  r.predicted.weighting = {p(Metric::w_u_mean), p(Metric::w_u_max), p(Metric::w_kinetic_energy)};
  warn_unphysical(r.predicted, r.warnings);
  decide(query, r);
  return r;
}

}  // namespace ccm::study
