#include "study/grid/point_parameters.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <stdexcept>

namespace ccm::study {
namespace {

std::string positive_problem(double v) {
  return v > 0.0 ? std::string() : fmt::format("must be > 0 (got {})", v);
}

std::string poisson_problem(double v) {
  return (v > -1.0 && v < 0.5) ? std::string() : fmt::format("must lie in (-1, 0.5) (got {})", v);
}

// A tet edge above half the diameter is more than Gmsh accepts on a sphere (its radius).
std::string mesh_ratio_problem(double v) {
  return (v > 0.0 && v <= 0.5) ? std::string() : fmt::format("must lie in (0, 0.5] (got {})", v);
}

std::string unit_interval_problem(double v) {
  return (v >= 0.0 && v <= 1.0) ? std::string() : fmt::format("must lie in [0, 1] (got {})", v);
}

std::string non_negative_problem(double v) {
  return v >= 0.0 ? std::string() : fmt::format("must be >= 0 (got {})", v);
}

using Check = std::function<std::string(double)>;

const std::map<std::string_view, Check>& axis_checks() {
  static const std::map<std::string_view, Check> checks = {
      {"ER", positive_problem},
      {"RLS", positive_problem},
      {"KE", positive_problem},
      {"nu", poisson_problem},
      {"artifact_mesh_size", positive_problem},
      {"impactor_mesh_ratio", mesh_ratio_problem},
      {"mesh_scale", positive_problem},
      {"penalty", positive_problem},
      {"penalty_scale", non_negative_problem},
      {"damping", non_negative_problem},
      {"restitution", unit_interval_problem},
      {"friction", non_negative_problem},
  };
  return checks;
}

void apply_other_axis(std::string_view name, double value, PointParameters& p) {
  if (name == "nu") {
    p.artifact.nu = value;
    p.impactor_nu = value;
  } else if (name == "artifact_mesh_size") {
    p.artifact.mesh_size = value;
  } else if (name == "impactor_mesh_ratio") {
    p.impactor_mesh_size = value * p.impactor_diameter;
  } else if (name == "penalty") {
    p.contact.penalty = value;
  } else if (name == "penalty_scale") {  // 0: the thesis's K_P per point
    p.contact.penalty_mode = value > 0.0 ? PenaltyMode::element : PenaltyMode::per_point;
    if (value > 0.0) p.contact.penalty_scale = value;
  } else if (name == "damping") {
    p.contact.damping = value;
  } else if (name == "restitution") {
    p.contact.restitution = value;
  } else if (name == "friction") {
    p.contact.friction = value;
  } else if (name != "mesh_scale") {  // applied last, on top of the mesh sizes
    throw std::invalid_argument(fmt::format("unknown grid axis '{}'", name));
  }
}

}  // namespace

const std::vector<std::string_view>& other_axis_names() {
  static const std::vector<std::string_view> names = {"nu",
                                                      "artifact_mesh_size",
                                                      "impactor_mesh_ratio",
                                                      "mesh_scale",
                                                      "penalty",
                                                      "penalty_scale",
                                                      "damping",
                                                      "restitution",
                                                      "friction"};
  return names;
}

std::string axis_value_problem(std::string_view name, double value) {
  const auto it = axis_checks().find(name);
  if (it == axis_checks().end()) return fmt::format("unknown grid axis '{}'", name);
  if (!std::isfinite(value)) return fmt::format("must be finite (got {})", value);
  return it->second(value);
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
  if (const auto it = point.other_axes.find("mesh_scale"); it != point.other_axes.end()) {
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
