// The axes a grid may sweep besides ER, RLS and KE (GridPoint::other_axes, stored by name): one
// enum and one name table. Everything that depends on the axis (its check, how it changes a
// point's parameters) is a switch over the enum, so a new axis that is not handled everywhere
// does not compile without warnings (-Wswitch).
#pragma once

#include <array>
#include <optional>
#include <string_view>

namespace ccm::study {

enum class GridAxis {
  nu,                   // Poisson's ratio of both bodies
  artifact_mesh_size,   // the artifact's tet edge [m]
  impactor_mesh_ratio,  // the impactor's tet edge / D_I
  mesh_scale,           // a factor on both mesh sizes (convergence runs)
  penalty,              // K_P [N/m] (rigid model)
  penalty_scale,        // s >= 0 (rigid model): 0 the thesis's K_P per point, s > 0 the
                        // element-scaled penalty s K A^2 / V
  damping,              // zeta, the penalty's dashpot, fraction of critical (rigid model)
  restitution,          // e (ccm model)
  friction,             // mu (ccm model)
  density_ratio         // rho_I / rho_A: the impactor's density over the artifact's
};

struct GridAxisName {
  GridAxis axis;
  std::string_view name;
};

// The name table, in the order the docs list the axes.
inline constexpr std::array<GridAxisName, 10> kGridAxisNames = {{
    {GridAxis::nu, "nu"},
    {GridAxis::artifact_mesh_size, "artifact_mesh_size"},
    {GridAxis::impactor_mesh_ratio, "impactor_mesh_ratio"},
    {GridAxis::mesh_scale, "mesh_scale"},
    {GridAxis::penalty, "penalty"},
    {GridAxis::penalty_scale, "penalty_scale"},
    {GridAxis::damping, "damping"},
    {GridAxis::restitution, "restitution"},
    {GridAxis::friction, "friction"},
    {GridAxis::density_ratio, "density_ratio"},
}};

constexpr std::string_view to_string(GridAxis axis) {
  for (const GridAxisName& a : kGridAxisNames)
    if (a.axis == axis) return a.name;
  return {};
}

constexpr std::optional<GridAxis> parse_grid_axis(std::string_view name) {
  for (const GridAxisName& a : kGridAxisNames)
    if (a.name == name) return a.axis;
  return std::nullopt;
}

}  // namespace ccm::study
