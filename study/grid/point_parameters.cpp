#include "study/grid/point_parameters.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "engine/core/parameter_ranges.hpp"

namespace ccm::study {
namespace {

std::string positive_problem(double v) {
  return v > 0.0 ? std::string() : fmt::format("must be > 0 (got {})", v);
}

// A tet edge above half the diameter is more than Gmsh accepts on a sphere (its radius).
std::string mesh_ratio_problem(double v) {
  return (v > 0.0 && v <= 0.5) ? std::string() : fmt::format("must lie in (0, 0.5] (got {})", v);
}

std::string non_negative_problem(double v) {
  return v >= 0.0 ? std::string() : fmt::format("must be >= 0 (got {})", v);
}

// The allowed values of an axis: empty when `value` is allowed, else the problem.
std::string axis_problem(GridAxis axis, double value) {
  switch (axis) {
    case GridAxis::nu:
      return kPoissonRange.problem(value);
    case GridAxis::impactor_mesh_ratio:
      return mesh_ratio_problem(value);
    case GridAxis::artifact_mesh_size:
    case GridAxis::mesh_scale:
    case GridAxis::penalty:
    case GridAxis::density_ratio:
      return positive_problem(value);
    case GridAxis::penalty_scale:  // 0: the per-point K_P
      return non_negative_problem(value);
    case GridAxis::damping:
      return kDampingRange.problem(value);
    case GridAxis::friction:
      return kFrictionRange.problem(value);
    case GridAxis::restitution:
      return kRestitutionRange.problem(value);
  }
  return fmt::format("unknown grid axis {}", static_cast<int>(axis));
}

// The point's parameters with one axis value applied (mesh_scale is applied last, on top of the
// mesh sizes, by point_parameters).
void apply_axis(GridAxis axis, double value, PointParameters& p) {
  switch (axis) {
    case GridAxis::nu:
      p.artifact.nu = value;
      p.impactor_nu = value;
      return;
    case GridAxis::artifact_mesh_size:
      p.artifact.mesh_size = value;
      return;
    case GridAxis::impactor_mesh_ratio:
      p.impactor_mesh_size = value * p.impactor_diameter;
      return;
    case GridAxis::mesh_scale:
      return;
    case GridAxis::penalty:
      p.contact.penalty = value;
      return;
    case GridAxis::penalty_scale:  // 0: the thesis's K_P per point
      p.contact.penalty_mode = value > 0.0 ? PenaltyMode::element : PenaltyMode::per_point;
      if (value > 0.0) p.contact.penalty_scale = value;
      return;
    case GridAxis::damping:
      p.contact.damping = value;
      return;
    case GridAxis::restitution:
      p.contact.restitution = value;
      return;
    case GridAxis::friction:
      p.contact.friction = value;
      return;
    case GridAxis::density_ratio:
      p.impactor_rho = value * p.artifact.rho;
      return;
  }
}

void apply_other_axis(std::string_view name, double value, PointParameters& p) {
  const std::optional<GridAxis> axis = parse_grid_axis(name);
  if (!axis) throw std::invalid_argument(fmt::format("unknown grid axis '{}'", name));
  apply_axis(*axis, value, p);
}

}  // namespace

const std::vector<std::string_view>& other_axis_names() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> out;
    for (const GridAxisName& a : kGridAxisNames) out.push_back(a.name);
    return out;
  }();
  return names;
}

std::string axis_value_problem(std::string_view name, double value) {
  const bool main_axis = name == "ER" || name == "RLS" || name == "KE";
  const std::optional<GridAxis> axis = parse_grid_axis(name);
  if (!main_axis && !axis) return fmt::format("unknown grid axis '{}'", name);
  if (!std::isfinite(value)) return fmt::format("must be finite (got {})", value);
  return main_axis ? positive_problem(value) : axis_problem(*axis, value);
}

PointParameters point_parameters(const GridSpec& spec, const GridPoint& point) {
  PointParameters p;
  p.artifact = spec.artifact;
  p.impactor_E = point.modulus_ratio * spec.artifact.E;             // eq. 2.32
  p.impactor_diameter = point.length_ratio * spec.artifact.length;  // eq. 2.33
  p.impactor_nu = spec.impactor.nu;
  p.impactor_rho = spec.impactor.rho;
  p.impactor_mesh_size = spec.impactor.mesh_size_ratio * p.impactor_diameter;
  p.impactor_contact_mesh_size = spec.impactor.contact_mesh_size;
  p.impactor_contact_radius = spec.impactor.contact_radius;
  p.contact = spec.contact;
  for (const auto& [name, value] : point.other_axes) apply_other_axis(name, value, p);
  const auto it = point.other_axes.find(std::string(to_string(GridAxis::mesh_scale)));
  if (it != point.other_axes.end()) {
    p.artifact.mesh_size *= it->second;
    p.artifact.contact_mesh_size *= it->second;
    p.impactor_mesh_size *= it->second;
    p.impactor_contact_mesh_size *= it->second;
  }
  // A refinement is never coarser than the body's own mesh.
  p.artifact.contact_mesh_size = std::min(p.artifact.contact_mesh_size, p.artifact.mesh_size);
  p.impactor_contact_mesh_size = std::min(p.impactor_contact_mesh_size, p.impactor_mesh_size);
  const double d = p.impactor_diameter;
  p.impactor_mass = p.impactor_rho * std::numbers::pi * d * d * d / 6.0;
  p.impact_speed = std::sqrt(2.0 * point.kinetic_energy / p.impactor_mass);  // KE = m v^2 / 2
  p.gap = p.impact_speed * spec.time.contact_time;
  return p;
}

}  // namespace ccm::study
