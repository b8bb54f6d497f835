#include "reports/figures/comparison_section.hpp"

#include <fmt/format.h>

namespace ccm::reports {
namespace {

std::string optional_cell(const std::optional<double>& v) { return v ? cell(*v) : "-"; }

}  // namespace

Section comparison_section(const std::vector<db::ComparisonRow>& comparisons) {
  Section s{.id = "designs", .title = "Your designs compared"};
  if (comparisons.empty()) {
    s.paragraphs.push_back(
        "No design compared yet: `ccm compare SCENE --rigid BODY --db THIS_STORE` runs a scene "
        "as written and with the body rigid, and records here its measured answer beside this "
        "study's prediction (docs/compare.md).");
    return s;
  }
  int held = 0, predicted = 0;
  for (const db::ComparisonRow& c : comparisons)
    if (c.agrees) {
      ++predicted;
      held += *c.agrees ? 1 : 0;
    }
  s.paragraphs.push_back(fmt::format(
      "{} comparison{} of a design scene with bodies made rigid (`ccm compare`): the rigid run's "
      "worst final-state error against the deformable run, the measured cost ratio of the two "
      "step loops, and the answer by the rule at each comparison's threshold. Beside it, this "
      "study's prediction at the scene's own ER, RLS and KE*: it held in {} of the {} "
      "comparisons it could predict.",
      comparisons.size(), comparisons.size() == 1 ? "" : "s", held, predicted));
  Table t{.id = "designs",
          .caption = "One row per `ccm compare` recorded in this store, oldest first.",
          .header = {"scene", "rigid bodies", "worst final-state error", "cost ratio",
                     "measured answer", "study predicts", "held", "recorded (UTC)"}};
  for (const db::ComparisonRow& c : comparisons)
    t.rows.push_back({c.scene, c.rigid_bodies, optional_cell(c.worst_error),
                      optional_cell(c.cost_ratio),
                      c.answer.empty() ? "none: " + c.unusable : c.answer,
                      c.predicted.empty() ? "none: " + c.prediction_note : c.predicted,
                      c.agrees ? (*c.agrees ? "yes" : "no") : "-", c.recorded_at});
  s.tables.push_back(std::move(t));
  return s;
}

}  // namespace ccm::reports
