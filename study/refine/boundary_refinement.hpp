// Where a study's answer changes, and where to add points to locate it (`ccm study refine`,
// docs/refine.md). Along one axis (ER on the thesis grid, a coordinate path of a grid over a
// scene), the study's points fall on lines (every other axis fixed); between two neighbours on a
// line whose measured answers differ (the one rule, study/recommend/decision_rule.hpp) lies the
// boundary, and its position is known to the interval's width. An interval is split at its
// middle (geometric on an axis whose values on the line share a sign, else arithmetic) while it
// is wider than the tolerance; once every boundary is located, so are intervals next to a point
// whose answer the fits flag (their fitted answer differs or could flip within the leave-one-out
// error). Plans only: runs nothing.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "records/grid_point.hpp"
#include "study/recommend/recommendation.hpp"

namespace ccm::study {

// The axis refined: "ER" or a template coordinate "axes.<path>" (GridPoint::other_axes).
double axis_coordinate(const GridPoint& point, std::string_view axis);
void set_axis_coordinate(GridPoint& point, std::string_view axis, double value);

struct RefineInterval {
  std::string line;               // the line's other axes, for people: "RLS 0.5, KE 10 J"
  GridPoint lo, hi;               // neighbours on the line, lo below hi on the axis
  double lo_x = 0.0, hi_x = 0.0;  // their values on the axis
  ImpactModel lo_answer = ImpactModel::ccm, hi_answer = ImpactModel::ccm;
  bool geometric = true;  // widths in decades (log10) when true, else in the axis's units
  double width = 0.0;
  bool boundary = false;   // the answers differ
  bool uncertain = false;  // the same answer, but a neighbour's is flagged by the fits
  // What changes across a boundary: the errors (within max_error at one end only), the cost
  // (RTR > 1 at one end only), or both. A cost boundary sits where RTR crosses 1, which a
  // sitting measures to tens of percent: it moves between sittings, an error boundary does not.
  bool errors_change = false, cost_changes = false;
  double middle() const;  // where it is split
};

struct RefinePlan {
  std::vector<RefineInterval> boundaries;  // every interval where the answer changes
  std::vector<RefineInterval> to_split;    // wider than the tolerance, widest first: the
                                           // boundaries, or when none, the uncertain intervals
};

// `decisions`: every usable point of the study (decide_grid_points). `tolerance`: the width at
// which an interval is resolved (decades on a geometric line, else the axis's units).
RefinePlan plan_refinement(std::span<const PointDecision> decisions, std::string_view axis,
                           double tolerance);

// "RLS 0.5, KE 10: ccm at ER 100, rigid at ER 1e+04 (2 decades; tolerance 0.25: not resolved;
// the errors change)"
std::string boundary_text(const RefineInterval& interval, std::string_view axis, double tolerance);

}  // namespace ccm::study
