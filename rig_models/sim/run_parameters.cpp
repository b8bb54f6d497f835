#include "rig_models/sim/run_parameters.hpp"

#include <fmt/format.h>

#include <array>
#include <stdexcept>

namespace ccm::rig {

std::string_view name_of(DriveKind kind) {
  return kind == DriveKind::open_loop ? "open-loop" : "physical";
}

std::optional<DriveKind> parse_drive(std::string_view name) {
  if (name == "open-loop") return DriveKind::open_loop;
  if (name == "physical") return DriveKind::physical;
  return std::nullopt;
}

RunParameters default_parameters(const RigCaseTable& table, const RigCase& c) {
  RunParameters p;
  if (c.pivot_friction) {
    p.mu_s = c.pivot_friction->mu_s;
    p.mu_k = c.pivot_friction->mu_k;
  }
  p.track_static_friction = table.drive.track_static_friction.value;
  p.track_friction = table.drive.track_friction.value;
  p.track_damping = table.drive.track_damping.value;
  p.spring_stiffness = table.rig.spring_stiffness.value;
  p.clamp_stiffness = table.rig.clamp_stiffness.value;
  p.clamp_damping = table.rig.clamp_damping.value;
  p.mat_stiffness = table.rig.mat_stiffness.value;
  p.mat_damping = table.rig.mat_damping.value;
  return p;
}

std::string parameter_problem(std::string_view name, const RigCase& c) {
  bool known = false;
  for (std::string_view n : kRunParameterNames) known = known || n == name;
  if (!known)
    return fmt::format("unknown parameter '{}' (known: {})", name,
                       fmt::join(kRunParameterNames, ", "));
  if (name == "spring_stiffness" && c.impactor != ImpactorKind::flexible)
    return fmt::format("'{}' needs a flexible impactor; {} has a rigid one", name, c.code);
  if ((name == "clamp_stiffness" || name == "clamp_damping") && c.artifact != ArtifactKind::fixed)
    return fmt::format("'{}' holds a Fixed artifact's pin; {} turns freely on its pin", name,
                       c.code);
  return {};
}

namespace {

// The parameters held as plain numbers, by name (mu_s and mu_k are optional: a Fixed case's pin
// has no friction until one is given).
struct NumberParameter {
  std::string_view name;
  double RunParameters::*member;
};
constexpr std::array<NumberParameter, 8> kNumberParameters = {{
    {"track_static_friction", &RunParameters::track_static_friction},
    {"track_friction", &RunParameters::track_friction},
    {"track_damping", &RunParameters::track_damping},
    {"spring_stiffness", &RunParameters::spring_stiffness},
    {"clamp_stiffness", &RunParameters::clamp_stiffness},
    {"clamp_damping", &RunParameters::clamp_damping},
    {"mat_stiffness", &RunParameters::mat_stiffness},
    {"mat_damping", &RunParameters::mat_damping},
}};

double RunParameters::*number_member(std::string_view name) {
  for (const NumberParameter& n : kNumberParameters)
    if (n.name == name) return n.member;
  throw std::invalid_argument(fmt::format("unknown rig parameter '{}'", name));
}

}  // namespace

double get_parameter(const RunParameters& p, std::string_view name) {
  if (name == "mu_s") return p.mu_s.value_or(kFrictionalFixedMuS);
  if (name == "mu_k") return p.mu_k.value_or(kFrictionalFixedMuK);
  return p.*number_member(name);
}

void set_parameter(RunParameters& p, std::string_view name, double value) {
  if (name == "mu_s" || name == "mu_k") {
    // Setting one coefficient of a Fixed case's frictionless clamp makes it frictional: both exist.
    if (!p.mu_s) p.mu_s = kFrictionalFixedMuS;
    if (!p.mu_k) p.mu_k = kFrictionalFixedMuK;
    (name == "mu_s" ? *p.mu_s : *p.mu_k) = value;
    return;
  }
  p.*number_member(name) = value;
}

std::string describe(const RunParameters& p, const RigCase& c, DriveKind drive) {
  std::string s = p.mu_s ? fmt::format("pin mu_s {:g}, mu_k {:g}", *p.mu_s, *p.mu_k)
                         : std::string("pin frictionless");
  if (c.artifact == ArtifactKind::fixed)
    s += fmt::format(", clamp {:g} N m/rad, {:g} N m s/rad", p.clamp_stiffness, p.clamp_damping);
  s += p.mat_stiffness > 0.0
           ? fmt::format(", sensor mat {:g} N/m^n, lambda {:g} s/m", p.mat_stiffness, p.mat_damping)
           : std::string(", exact contact");
  s += fmt::format(", track mu_s {:g}, mu_k {:g}, c {:g} N s/m{}", p.track_static_friction,
                   p.track_friction, p.track_damping,
                   drive == DriveKind::open_loop ? " (from the contact onset)" : "");
  if (c.impactor == ImpactorKind::flexible) s += fmt::format(", K_s {:g} N/m", p.spring_stiffness);
  return s;
}

}  // namespace ccm::rig
