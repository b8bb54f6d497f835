// Names, axis labels and case labels shared by the report's figures and tables.
#pragma once

#include <string>
#include <vector>

#include "records/grid_point.hpp"
#include "records/run_record.hpp"
#include "study/metrics/metric.hpp"

namespace ccm::reports {

std::string model_label(study::ImpactModel model);  // "CCM (meshed sphere, DCR)", ...
// "ER 1e+06, RLS 0.5, KE 100 J", then every other axis of the point ("mesh_scale 0.5", "nu
// 0.3"), so that no two points of a study share a label.
std::string case_label(const study::GridPoint& p);
// The three main axes only: "ER 1e+06, RLS 0.5, KE 100 J" (a convergence point's case).
std::string main_case_label(const study::GridPoint& p);
std::string metric_label(study::Metric metric);  // "final-state error in u_max [-]", ...

// The distinct impactor kinetic energies of the given points, ascending.
std::vector<double> kinetic_energy_levels(const std::vector<study::GridPoint>& points);

}  // namespace ccm::reports
