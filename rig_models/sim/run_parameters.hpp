// The parameters of a rig run that a user may change and `ccm rig calibrate` may tune, by name:
//   mu_s, mu_k        pin friction (eq. 3.4). A free artifact always has them (cases.toml); a
//                     fixed one turns on its clamp without friction unless they are given, which
//                     adds the thesis's frictional "fixed" pin (3.4.1: mu_s = 50, mu_k = 0.99)
//   track_static_friction, track_friction
//                     static and kinetic Coulomb coefficients of the track (engine/bc/
//                     track_friction.hpp; physical drive throughout, open loop after the onset)
//   track_damping     N s/m, viscous coefficient of the track
//   spring_stiffness  N/m, K_s of the flexible impactor (eq. 3.1)
//   clamp_stiffness   N m/rad, the Fixed artifact's pin clamp: a torsional spring about the pin
//   clamp_damping     N m s/rad, its damper (engine/bc/pin_joint.hpp, PJ.1)
//   mat_stiffness     N/m^n, the sensor mat's contact law (sim/sensor_mat.hpp; 0: exact contact)
//   mat_damping       s/m, its Hunt-Crossley lambda
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "rig_models/cases/rig_case.hpp"

namespace ccm::rig {

enum class DriveKind { open_loop, physical };
std::string_view name_of(DriveKind kind);
std::optional<DriveKind> parse_drive(std::string_view name);  // "open-loop", "physical"

struct RunParameters {
  std::optional<double> mu_s, mu_k;
  double track_static_friction = 0.0, track_friction = 0.0;
  double track_damping = 0.0;
  double spring_stiffness = 0.0;
  double clamp_stiffness = 0.0, clamp_damping = 0.0;
  double mat_stiffness = 0.0, mat_damping = 0.0;
};

// clang-format off
inline constexpr std::array<std::string_view, 10> kRunParameterNames = {
    "mu_s", "mu_k", "track_static_friction", "track_friction", "track_damping",
    "spring_stiffness", "clamp_stiffness", "clamp_damping", "mat_stiffness", "mat_damping"};
// clang-format on

// The case file's values for this case.
RunParameters default_parameters(const RigCaseTable& table, const RigCase& c);

// The fixed case's frictional pin of thesis 3.4.1, used when calibration asks for mu_s or mu_k
// on a fixed artifact.
inline constexpr double kFrictionalFixedMuS = 50.0;
inline constexpr double kFrictionalFixedMuK = 0.99;

// Why `name` does not apply to this case and drive (empty when it does): an unknown name, the
// spring's without a flexible impactor, the clamp's without a Fixed artifact.
std::string parameter_problem(std::string_view name, const RigCase& c);

// The value of `name` (mu_s, mu_k of a fixed case: the frictional-fixed pin's when unset), and
// setting it. Throws std::invalid_argument for an unknown name.
double get_parameter(const RunParameters& p, std::string_view name);
void set_parameter(RunParameters& p, std::string_view name, double value);

// "mu_s 0.2, mu_k 0.1, ..." for messages and tables.
std::string describe(const RunParameters& p, const RigCase& c, DriveKind drive);

}  // namespace ccm::rig
