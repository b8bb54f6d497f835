#include "correlate/iso18571_rating.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace ccm::correlate {

namespace {

using Values = std::span<const double>;

void check_curves(Values reference, Values comparison, double sample_interval) {
  if (reference.size() != comparison.size())
    throw std::invalid_argument(fmt::format(
        "the curves must be sampled at the same instants: the reference has {} samples, the "
        "comparison {}",
        reference.size(), comparison.size()));
  if (reference.size() < 10)
    throw std::invalid_argument(
        fmt::format("a rating needs at least 10 samples; the curves have {}", reference.size()));
  if (!(sample_interval > 0.0) || !std::isfinite(sample_interval))
    throw std::invalid_argument(
        fmt::format("sample interval {} s must be a positive number", sample_interval));
  for (std::size_t i = 0; i < reference.size(); ++i)
    if (!std::isfinite(reference[i]) || !std::isfinite(comparison[i]))
      throw std::invalid_argument(fmt::format("sample {} is not a finite number", i));
}

double max_abs(Values v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

// Sum of |a_i - b_i| over sum of |b_i|: the relative L1 error of a against b.
double relative_l1(Values a, Values b) {
  double num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    num += std::abs(a[i] - b[i]);
    den += std::abs(b[i]);
  }
  if (den == 0.0) return num == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
  return num / den;
}

// The linear score of an error: 1 at 0, 0 at `limit` or more, raised to `exponent`.
double error_score(double error, double limit, double exponent) {
  if (error <= 0.0) return 1.0;
  if (error >= limit) return 0.0;
  return std::pow((limit - error) / limit, exponent);
}

// R.1.
double corridor_score(Values reference, Values comparison, const RatingParameters& p) {
  const double norm = max_abs(reference);
  const double inner = p.inner_corridor * norm;
  const double outer = p.outer_corridor * norm;
  double sum = 0.0;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    const double diff = std::abs(comparison[i] - reference[i]);
    if (diff < inner)
      sum += 1.0;
    else if (diff <= outer)
      sum += std::pow((outer - diff) / (outer - inner), p.corridor_exponent);
  }
  return sum / static_cast<double>(reference.size());
}

// Pearson's correlation coefficient of a and b; a constant pair correlates 1 if equal, else 0.
double pearson(Values a, Values b) {
  const double n = static_cast<double>(a.size());
  const double ma = std::accumulate(a.begin(), a.end(), 0.0) / n;
  const double mb = std::accumulate(b.begin(), b.end(), 0.0) / n;
  double sab = 0.0, saa = 0.0, sbb = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  if (saa == 0.0 || sbb == 0.0) return std::equal(a.begin(), a.end(), b.begin()) ? 1.0 : 0.0;
  return sab / std::sqrt(saa * sbb);
}

struct Shift {
  long samples = 0;  // > 0: the comparison lags the reference
  double correlation = 0.0;
  Values reference;  // the overlapping parts, aligned
  Values comparison;
};

// R.2's search: shifts 1 .. floor(eps_P N) both ways; the first strictly best one wins.
Shift best_shift(Values reference, Values comparison, const RatingParameters& p) {
  const std::size_t n = reference.size();
  const auto window =
      static_cast<std::size_t>(std::floor(static_cast<double>(n) * p.max_shift)) + 1;
  Shift best{0, pearson(reference, comparison), reference, comparison};
  for (std::size_t k = 1; k < window && k + 2 <= n; ++k) {
    const Values ref_early = reference.first(n - k), ref_late = reference.last(n - k);
    const Values cmp_early = comparison.first(n - k), cmp_late = comparison.last(n - k);
    // The comparison behind the reference: its sample i + k against the reference's i.
    const double lag = pearson(ref_early, cmp_late);
    if (lag > best.correlation) best = {static_cast<long>(k), lag, ref_early, cmp_late};
    const double lead = pearson(ref_late, cmp_early);  // and ahead of it
    if (lead > best.correlation) best = {-static_cast<long>(k), lead, ref_late, cmp_early};
  }
  return best;
}

double phase_score(const Shift& shift, std::size_t n, const RatingParameters& p) {
  if (shift.samples == 0) return 1.0;
  const double limit = static_cast<double>(n) * p.max_shift;
  return error_score(static_cast<double>(std::labs(shift.samples)), limit, p.phase_exponent);
}

// R.3's warping: the path through the band |i - j| < r of least summed squared difference with
// the steps (1, 0), (0, 1), (1, 1), each weighted 1; then the relative L1 error of the warped
// comparison against the warped reference. Only the band's step choices are stored (one byte a
// cell) and two rows of costs, so 10,000 samples need 20 MB, not 800.
double warped_magnitude_error(Values comparison, Values reference, const RatingParameters& p) {
  const long n = static_cast<long>(reference.size());
  const long r =
      std::min(n, std::max(1L, static_cast<long>(std::ceil(p.dtw_band * static_cast<double>(n)))));
  const long width = 2 * r - 1;  // j - i in (-r, r)
  constexpr double kInf = std::numeric_limits<double>::infinity();
  constexpr std::uint8_t kFromUp = 0, kFromLeft = 1, kFromDiagonal = 2;
  std::vector<std::uint8_t> step(static_cast<std::size_t>(n * width), kFromDiagonal);
  std::vector<double> previous(static_cast<std::size_t>(width), kInf);
  std::vector<double> current(static_cast<std::size_t>(width), kInf);
  auto band = [&](long i, long j) { return static_cast<std::size_t>(j - i + r - 1); };
  for (long i = 0; i < n; ++i) {
    std::fill(current.begin(), current.end(), kInf);
    for (long j = std::max(0L, i - r + 1); j <= std::min(n - 1, i + r - 1); ++j) {
      const double d =
          comparison[static_cast<std::size_t>(i)] - reference[static_cast<std::size_t>(j)];
      const double cost = d * d;
      if (i == 0 && j == 0) {
        current[band(i, j)] = cost;
        continue;
      }
      // Predecessors in the order the backtrack prefers on ties: (i-1, j), (i, j-1), (i-1, j-1).
      const double up = (i > 0 && j - (i - 1) < r) ? previous[band(i - 1, j)] : kInf;
      const double left = (j > 0 && i - (j - 1) < r) ? current[band(i, j - 1)] : kInf;
      const double diagonal = (i > 0 && j > 0) ? previous[band(i - 1, j - 1)] : kInf;
      std::uint8_t choice = kFromUp;
      double best = up;
      if (left < best) best = left, choice = kFromLeft;
      if (diagonal < best) best = diagonal, choice = kFromDiagonal;
      current[band(i, j)] = cost + best;
      step[static_cast<std::size_t>(i * width) + band(i, j)] = choice;
    }
    std::swap(previous, current);
  }
  std::vector<double> warped_c, warped_t;
  for (long i = n - 1, j = n - 1;;) {
    warped_c.push_back(comparison[static_cast<std::size_t>(i)]);
    warped_t.push_back(reference[static_cast<std::size_t>(j)]);
    if (i == 0 && j == 0) break;
    const std::uint8_t choice = i == 0   ? kFromLeft
                                : j == 0 ? kFromUp
                                         : step[static_cast<std::size_t>(i * width) + band(i, j)];
    if (choice != kFromLeft) --i;
    if (choice != kFromUp) --j;
  }
  return relative_l1(warped_c, warped_t);
}

// R.4's derivative: central differences (one-sided at the ends), then the mean of the 9 samples
// around each one, of 1, 3, 5 and 7 samples from the ends.
std::vector<double> smoothed_slope(Values v, double dt) {
  const std::size_t n = v.size();
  // The shifted parts keep at least 80 % of the 10 samples a rating needs.
  if (n < 8) throw std::logic_error("a smoothed slope needs at least 8 samples");
  std::vector<double> g(n);
  g[0] = (v[1] - v[0]) / dt;
  g[n - 1] = (v[n - 1] - v[n - 2]) / dt;
  for (std::size_t i = 1; i + 1 < n; ++i) g[i] = (v[i + 1] - v[i - 1]) / (2.0 * dt);
  std::vector<double> s(n, 0.0);
  for (std::size_t k = 0; k < 4; ++k) {
    const std::size_t width = 2 * k + 1;
    s[k] = std::accumulate(g.begin(), g.begin() + static_cast<std::ptrdiff_t>(width), 0.0) /
           static_cast<double>(width);
    s[n - 1 - k] = std::accumulate(g.end() - static_cast<std::ptrdiff_t>(width), g.end(), 0.0) /
                   static_cast<double>(width);
  }
  for (std::size_t i = 4; i + 4 < n; ++i)
    s[i] = std::accumulate(g.begin() + static_cast<std::ptrdiff_t>(i - 4),
                           g.begin() + static_cast<std::ptrdiff_t>(i + 5), 0.0) /
           9.0;
  return s;
}

}  // namespace

CurveRating iso18571_rating(Values reference, Values comparison, double sample_interval,
                            const RatingParameters& p) {
  check_curves(reference, comparison, sample_interval);
  if (max_abs(reference) == 0.0)
    throw std::invalid_argument("the reference curve is zero everywhere: it has no corridor");
  CurveRating out;
  out.corridor = corridor_score(reference, comparison, p);
  const Shift shift = best_shift(reference, comparison, p);
  out.shift_samples = shift.samples;
  out.shift_correlation = shift.correlation;
  out.phase = phase_score(shift, reference.size(), p);
  out.magnitude_error = warped_magnitude_error(shift.comparison, shift.reference, p);
  out.magnitude = error_score(out.magnitude_error, p.max_magnitude_error, p.magnitude_exponent);
  out.slope_error = relative_l1(smoothed_slope(shift.comparison, sample_interval),
                                smoothed_slope(shift.reference, sample_interval));
  out.slope = error_score(out.slope_error, p.max_slope_error, 1.0);
  out.overall = 0.4 * out.corridor + 0.2 * out.phase + 0.2 * out.magnitude + 0.2 * out.slope;
  out.grade = rating_grade(out.overall);
  return out;
}

RatingGrade rating_grade(double overall) {
  if (overall > 0.94) return RatingGrade::excellent;
  if (overall > 0.80) return RatingGrade::good;
  if (overall > 0.58) return RatingGrade::fair;
  return RatingGrade::poor;
}

std::string_view grade_name(RatingGrade grade) {
  switch (grade) {
    case RatingGrade::excellent:
      return "excellent";
    case RatingGrade::good:
      return "good";
    case RatingGrade::fair:
      return "fair";
    case RatingGrade::poor:
      return "poor";
  }
  return "poor";
}

}  // namespace ccm::correlate
