// The recommendation map: for each level of the grid's other axes and each studied KE level,
// the (ER, RLS) plane coloured by the model the decision rule (study/recommend/decision_rule.hpp)
// chooses on the fitted surfaces at a user-chosen error threshold, with the cells whose answer
// is unreliable marked and the measured grid points' own answers on top (thesis 2.8, App. B).
#pragma once

#include <span>

#include "reports/data/report_data.hpp"
#include "reports/figures/report_content.hpp"

namespace ccm::reports {

// Map resolution per axis: cells evaluated over the fitted range of log10 ER and RLS.
inline constexpr int kMapCells = 31;

// One cell of a map: its centre, the model recommended there and whether that is reliable.
struct MapCell {
  double modulus_ratio = 1.0, length_ratio = 1.0;
  study::ImpactModel model = study::ImpactModel::ccm;
  bool reliable = true;
};

// kMapCells x kMapCells cells evenly spaced over the (log10 ER, RLS) range of the final-state
// KE error fit at `kinetic_energy` and `axes`; empty when there is no such fit. Throws
// std::runtime_error when the fits lack a metric the decision needs.
std::vector<MapCell> recommendation_cells(const study::StudyFits& fits,
                                          std::span<const study::PointMetrics> measured,
                                          const study::AxisLevels& axes, double kinetic_energy,
                                          double max_error);

// Every map of the study (one per axis group and KE level), or paragraphs saying why not.
struct RecommendationMaps {
  std::vector<Figure> figures;
  std::vector<std::string> notes;
};
RecommendationMaps recommendation_maps(const ReportData& data, double max_error);

}  // namespace ccm::reports
