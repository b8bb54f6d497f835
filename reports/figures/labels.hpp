// Names, axis labels and case labels shared by the report's figures and tables.
#pragma once

#include <string>
#include <vector>

#include "study/grid/grid_point.hpp"
#include "study/metrics/metric.hpp"
#include "study/runner/run_record.hpp"

namespace ccm::reports {

std::string model_label(study::ImpactModel model);  // "CCM (meshed sphere, DCR)", ...
std::string case_label(const study::GridPoint& p);  // "ER 1e+06, RLS 0.5, KE 100 J"
std::string metric_label(study::Metric metric);     // "final-state error in u_max [-]", ...

// The distinct impactor kinetic energies of the given points, ascending.
std::vector<double> kinetic_energy_levels(const std::vector<study::GridPoint>& points);

}  // namespace ccm::reports
