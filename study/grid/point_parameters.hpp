// The physical parameters of one grid point: the grid's fixed parameters with the point's axis
// values applied, and the impact kinematics that follow from them (thesis 2.8).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "records/grid_point.hpp"
#include "study/grid/grid_axis.hpp"
#include "study/grid/grid_spec.hpp"

namespace ccm::study {

// The names of the axes a grid may sweep besides ER, RLS and KE (study/grid/grid_axis.hpp).
const std::vector<std::string_view>& other_axis_names();

// Empty when `value` is allowed for axis `name`, else the problem ("must be > 0 (got -1)").
// Also checks ER, RLS and KE under the names "ER", "RLS", "KE".
std::string axis_value_problem(std::string_view name, double value);

struct PointParameters {
  ArtifactSpec artifact;           // with nu and mesh size of the point
  double impactor_E = 0.0;         // E_I = ER E_A                      (eq. 2.32)
  double impactor_diameter = 0.0;  // D_I = RLS L_A                     (eq. 2.33)
  double impactor_nu = 0.0;
  double impactor_rho = 0.0;
  double impactor_mesh_size = 0.0;          // [m]
  double impactor_contact_mesh_size = 0.0;  // [m], 0: no refinement at the lowest point
  double impactor_contact_radius = 0.0;     // [m]
  double impactor_mass = 0.0;               // m_I = rho_I pi D_I^3 / 6 (the analytic sphere)
  double impact_speed = 0.0;                // v_I = sqrt(2 KE_I / m_I)
  double gap = 0.0;                         // surface to surface at t = 0: v_I t_c
  GridContact contact;
};

// Throws std::invalid_argument for an unknown other axis name (the parser rejects them first).
PointParameters point_parameters(const GridSpec& spec, const GridPoint& point);

}  // namespace ccm::study
