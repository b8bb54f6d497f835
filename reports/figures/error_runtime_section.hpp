// Error against runtime (thesis 2.8, what the thesis lacks): the final-state errors of every
// usable grid point against its runtime ratio; and, from the convergence mode, every run's
// final-state error against the finest CCM run of its point, against its wall time, with each
// model's accuracy per second.
#pragma once

#include "reports/data/report_data.hpp"
#include "reports/figures/report_content.hpp"
#include "study/metrics/convergence.hpp"

namespace ccm::reports {

Section error_runtime_section(const ReportData& data);

// The usable comparisons of the convergence runs among `data.runs`, ordered by case, model
// and mesh scale (finest first).
std::vector<study::ConvergenceRow> convergence_rows(const ReportData& data);

// One row per usable convergence run: point, case, model, role, mesh scale, elements, wall
// time, the three final-state errors and the accuracy per second.
Table convergence_table(const std::vector<study::ConvergenceRow>& rows);

}  // namespace ccm::reports
