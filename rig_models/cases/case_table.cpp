#include "rig_models/cases/case_table.hpp"

#include <fmt/format.h>

#include <utility>

namespace ccm::rig {
namespace {

void append_parameter(std::string& out, std::string_view name, const SourcedValue& v) {
  out += fmt::format("  {:<26} {:>12.6g} {:<7} {}\n", name, v.value, v.unit, v.source);
}

std::string parameters_section(const RigCaseTable& table) {
  const RigParameters& r = table.rig;
  const std::pair<std::string_view, const SourcedValue*> rows[] = {
      {"hanging mass", &r.hanging_mass},
      {"impactor mass M_i", &r.impactor_mass},
      {"spring stiffness K_s", &r.spring_stiffness},
      {"spring length L", &r.spring_length},
      {"spring cylinder diameter", &r.spring_cylinder_diameter},
      {"artifact mass", &r.artifact_mass},
      {"artifact J about pivot", &r.artifact_inertia_pivot},
      {"pin clamp stiffness", &r.clamp_stiffness},
      {"pin clamp damping", &r.clamp_damping},
      {"sensor mat stiffness", &r.mat_stiffness},
      {"sensor mat exponent", &r.mat_exponent},
      {"sensor mat damping", &r.mat_damping},
      {"pivot to sensor", &r.pivot_to_sensor},
      {"sensor area A_p", &r.sensor_area},
      {"sensor deadband", &r.sensor_deadband},
      {"pressure rate", &r.pressure_rate},
      {"angle rate", &r.angle_rate},
      {"velocity rate", &r.velocity_rate},
      {"low-pass cutoff", &r.low_pass_cutoff},
      {"trials per case", &r.trials_per_case}};
  std::string out = fmt::format("Benchtop rig ({})\n", table.source.string());
  for (const auto& [name, value] : rows) append_parameter(out, name, *value);
  out += fmt::format("  {:<26} {:>12.6g} {:<7} eq. 3.1, E_s = K_s L / A, A = pi d^2 / 4\n",
                     "spring cylinder E_s", spring_modulus(r), "Pa");
  const DriveParameters& d = table.drive;
  const SimulationParameters& sim = table.simulation;
  const std::pair<std::string_view, const SourcedValue*> drive_rows[] = {
      {"V_i smoothing half window", &d.velocity_smoothing},
      {"track static coefficient", &d.track_static_friction},
      {"track kinetic coefficient", &d.track_friction},
      {"track viscous coefficient", &d.track_damping},
      {"string stiffness", &d.string_stiffness},
      {"string damping", &d.string_damping},
      {"run lead before contact", &sim.lead},
      {"output interval", &sim.output_interval},
      {"run after contact (no data)", &sim.after_contact}};
  out += "Drive and simulation\n";
  for (const auto& [name, value] : drive_rows) append_parameter(out, name, *value);
  return out;
}

std::string friction_cell(const RigCase& c) {
  if (!c.pivot_friction) return "clamped (rig table)";
  return fmt::format("mu_s {:g}, mu_k {:g}", c.pivot_friction->mu_s, c.pivot_friction->mu_k);
}

}  // namespace

std::string format_case_table(const RigCaseTable& table) {
  std::string out = parameters_section(table);
  out += fmt::format("\n{:>2}  {:<5}  {:>11}  {:<8}  {:<8}  {:<20}  {}\n", "#", "code",
                     "speed [m/s]", "impactor", "artifact", "pivot", "source");
  for (const RigCase& c : table.cases)
    out += fmt::format("{:>2}  {:<5}  {:>11.2f}  {:<8}  {:<8}  {:<20}  {}\n", c.number, c.code,
                       c.target_speed.value, name_of(c.impactor), name_of(c.artifact),
                       friction_cell(c), c.source);
  return out;
}

}  // namespace ccm::rig
