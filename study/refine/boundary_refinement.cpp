#include "study/refine/boundary_refinement.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "study/grid/grid_spec.hpp"

namespace ccm::study {
namespace {

constexpr std::string_view kModulusRatio = "ER";

// Everything of a point but the refined axis, as a key and as text.
std::string line_of(const GridPoint& p, std::string_view axis) {
  std::string text;
  const auto add = [&](std::string_view name, double v) {
    text += fmt::format("{}{} {:g}", text.empty() ? "" : ", ", name, v);
  };
  if (axis == kModulusRatio) {
    add("RLS", p.length_ratio);
    add("KE", p.kinetic_energy);
  }
  for (const auto& [name, value] : p.other_axes)
    if (name != axis)
      add(name.starts_with(kTemplateAxisPrefix) ? name.substr(kTemplateAxisPrefix.size()) : name,
          value);
  return text;
}

struct LinePoint {
  const PointDecision* decision;
  double x;
};

bool one_sign(const std::vector<LinePoint>& line) {
  return std::all_of(line.begin(), line.end(), [](const LinePoint& p) { return p.x > 0.0; }) ||
         std::all_of(line.begin(), line.end(), [](const LinePoint& p) { return p.x < 0.0; });
}

RefineInterval interval(const std::string& text, const LinePoint& a, const LinePoint& b,
                        bool geometric) {
  RefineInterval i;
  i.line = text;
  i.lo = a.decision->point->point;
  i.hi = b.decision->point->point;
  i.lo_x = a.x;
  i.hi_x = b.x;
  i.lo_answer = a.decision->measured.model;
  i.hi_answer = b.decision->measured.model;
  i.geometric = geometric;
  i.width = geometric ? std::abs(std::log10(b.x / a.x)) : b.x - a.x;
  i.boundary = i.lo_answer != i.hi_answer;
  i.errors_change =
      a.decision->measured.rigid_within_error != b.decision->measured.rigid_within_error;
  i.cost_changes = a.decision->measured.rigid_cheaper != b.decision->measured.rigid_cheaper;
  i.uncertain = !i.boundary && (a.decision->flagged() || b.decision->flagged());
  return i;
}

}  // namespace

double axis_coordinate(const GridPoint& point, std::string_view axis) {
  if (axis == kModulusRatio) return point.modulus_ratio;
  const auto it = point.other_axes.find(std::string(axis));
  if (it == point.other_axes.end())
    throw std::invalid_argument(fmt::format("the point has no axis \"{}\"", axis));
  return it->second;
}

void set_axis_coordinate(GridPoint& point, std::string_view axis, double value) {
  if (axis == kModulusRatio)
    point.modulus_ratio = value;
  else
    point.other_axes.at(std::string(axis)) = value;
}

double RefineInterval::middle() const {
  if (!geometric) return 0.5 * (lo_x + hi_x);
  return std::copysign(std::sqrt(lo_x * hi_x), lo_x);  // lo_x hi_x > 0 on a geometric line
}

std::string boundary_text(const RefineInterval& i, std::string_view axis, double tolerance) {
  const char* cause = i.errors_change && i.cost_changes ? "the errors and the cost change"
                      : i.errors_change                 ? "the errors change"
                                                        : "the cost changes (RTR crosses 1)";
  return fmt::format("{}: {} at {} {:g}, {} at {} {:g} ({:.3g}{}; tolerance {:g}: {}; {})",
                     i.line.empty() ? "the line" : i.line, to_string(i.lo_answer), axis, i.lo_x,
                     to_string(i.hi_answer), axis, i.hi_x, i.width, i.geometric ? " decades" : "",
                     tolerance, i.width <= tolerance ? "resolved" : "not resolved", cause);
}

RefinePlan plan_refinement(std::span<const PointDecision> decisions, std::string_view axis,
                           double tolerance) {
  std::map<std::string, std::vector<LinePoint>> lines;
  for (const PointDecision& d : decisions)
    lines[line_of(d.point->point, axis)].push_back({&d, axis_coordinate(d.point->point, axis)});
  RefinePlan plan;
  std::vector<RefineInterval> uncertain;
  for (auto& [text, line] : lines) {
    std::sort(line.begin(), line.end(),
              [](const LinePoint& a, const LinePoint& b) { return a.x < b.x; });
    const bool geometric = one_sign(line);
    for (std::size_t k = 1; k < line.size(); ++k) {
      const RefineInterval i = interval(text, line[k - 1], line[k], geometric);
      if (i.boundary) plan.boundaries.push_back(i);
      if (i.width <= tolerance) continue;
      if (i.boundary) plan.to_split.push_back(i);
      if (i.uncertain) uncertain.push_back(i);
    }
  }
  const auto wider = [](const RefineInterval& a, const RefineInterval& b) {
    return a.width > b.width;
  };
  std::stable_sort(plan.to_split.begin(), plan.to_split.end(), wider);
  if (plan.to_split.empty()) {  // every boundary located: where the fits are unsure
    std::stable_sort(uncertain.begin(), uncertain.end(), wider);
    plan.to_split = std::move(uncertain);
  }
  return plan;
}

}  // namespace ccm::study
