// The benchtop rig of thesis chapter 3 and its 12 cases (Table 3.2), every number with its
// source: a thesis section or equation, or a stated assumption where the thesis is silent.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ccm::rig {

// A number from the case file with its unit and where it comes from.
struct SourcedValue {
  double value = 0.0;
  std::string unit;
  std::string source;
};

// What every case shares.
struct RigParameters {
  SourcedValue hanging_mass;              // kg, the weight that pulls the impactor
  SourcedValue impactor_mass;             // kg, M_i, impactor assembly on its track
  SourcedValue spring_stiffness;          // N/m, K_s of the flexible impactor's spring
  SourcedValue spring_length;             // m, L in E_s = K_s L / A
  SourcedValue spring_cylinder_diameter;  // m, the cylinder that stands in for the spring
  SourcedValue artifact_mass;             // kg, the rotating artifact segment
  SourcedValue artifact_inertia_pivot;    // kg m^2, J about the centre of rotation
  SourcedValue clamp_stiffness;           // N m/rad, the Fixed artifact's pin clamp (torsional)
  SourcedValue clamp_damping;             // N m s/rad, its damper
  SourcedValue mat_stiffness;             // N/m^n, the sensor mat's law (0: exact contact)
  SourcedValue mat_exponent;              // 1, its n
  SourcedValue mat_damping;               // s/m, its Hunt-Crossley lambda
  SourcedValue pivot_to_sensor;           // m, centre of rotation to the contact point
  SourcedValue sensor_area;               // m^2, A_p of the pressure sensor (eq. 3.8)
  SourcedValue sensor_deadband;           // kPa, pressures below read 0
  SourcedValue pressure_rate;             // Hz
  SourcedValue angle_rate;                // Hz
  SourcedValue velocity_rate;             // Hz
  SourcedValue low_pass_cutoff;           // Hz
  SourcedValue trials_per_case;           // count
};

// How the impactor is driven (thesis 3.3.2): the open-loop drive's smoothing of the measured
// velocity, and the physical drive's string and track (the future work of 3.3.2 and 3.5).
struct DriveParameters {
  SourcedValue velocity_smoothing;     // s, half window of the local fit of V_i (open loop)
  SourcedValue track_static_friction;  // 1, static Coulomb coefficient of the track
  SourcedValue track_friction;         // 1, its kinetic coefficient
  SourcedValue track_damping;          // N s/m, viscous coefficient of the track
  SourcedValue string_stiffness;       // N/m, string, pulley and bracket in series
  SourcedValue string_damping;         // N s/m, while the string is taut
};

// The simulated window and output.
struct SimulationParameters {
  SourcedValue lead;             // s, the open-loop run starts this long before contact
  SourcedValue output_interval;  // s, between sampled states
  SourcedValue after_contact;    // s, run length after the estimated contact without data
};

// A = pi d^2 / 4, the spring cylinder's cross-section [m^2].
double spring_cylinder_area(const RigParameters& rig);

// E_s = K_s L / A   (thesis eq. 3.1), the spring cylinder's Young's modulus [Pa].
double spring_modulus(const RigParameters& rig);

enum class ImpactorKind { rigid, flexible };
enum class ArtifactKind { fixed, free };

std::string_view name_of(ImpactorKind kind);
std::string_view name_of(ArtifactKind kind);

// Coulomb friction at the free artifact's pin (eqs. 3.2-3.6).
struct PivotFriction {
  double mu_s = 0.0;
  double mu_k = 0.0;
  std::string source;
};

struct RigCase {
  int number = 0;    // 1..12, Table 3.2
  std::string code;  // RX025 ... FF100
  SourcedValue target_speed;
  ImpactorKind impactor = ImpactorKind::rigid;
  ArtifactKind artifact = ArtifactKind::fixed;
  std::optional<PivotFriction> pivot_friction;  // free artifacts only
  std::string source;
};

struct RigCaseTable {
  std::filesystem::path source;
  RigParameters rig;
  DriveParameters drive;
  SimulationParameters simulation;
  std::vector<RigCase> cases;  // in Table 3.2 order

  // The case with this code; throws std::out_of_range naming it when there is none.
  const RigCase& find(std::string_view code) const;
};

}  // namespace ccm::rig
