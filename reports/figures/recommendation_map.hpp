// The recommendation map: for each studied KE level, the (ER, RLS) plane coloured by the model
// `study::recommend` chooses at a user-chosen error threshold (thesis 2.8, App. B).
#pragma once

#include "reports/data/report_data.hpp"
#include "reports/figures/report_content.hpp"

namespace ccm::reports {

// Map resolution per axis: cells evaluated over the fitted range of log10 ER and RLS.
inline constexpr int kMapCells = 31;

// One cell of a map: its centre and the model recommended there.
struct MapCell {
  double modulus_ratio = 1.0, length_ratio = 1.0;
  study::ImpactModel model = study::ImpactModel::ccm;
};

// kMapCells x kMapCells cells evenly spaced over the (log10 ER, RLS) range of the final-state
// KE error fit at `kinetic_energy`; empty when there is no such fit. Throws std::runtime_error
// when the fits lack a metric the decision needs.
std::vector<MapCell> recommendation_cells(const study::StudyFits& fits, double kinetic_energy,
                                          double max_error);

Section recommendation_section(const ReportData& data, double max_error);

}  // namespace ccm::reports
