// The benchtop rig as an engine model (thesis 3.3.1-3.3.2): the impactor's parts (carriage, rod
// and, when flexible, the spring cylinder of eq. 3.1) and the artifact's (PVC envelope over a
// two-part core with stabilizers, hanging from the pin), meshed by rig_mesher.hpp, with the
// densities tuned to the case file's masses and inertia, and the named node sets and surfaces a
// run needs: the pin's bore, the track guide, the drive surface, the contact surfaces, the
// sensor patch and the tracked nodes. Knows the rig, not how a run is driven.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "engine/solver/model.hpp"
#include "rig_models/cases/rig_case.hpp"
#include "rig_models/geometry/rig_geometry.hpp"

namespace ccm::rig {

// The model's node sets a run's joints select (rig_models/sim/rig_scene.hpp), beside each part's
// ("<part>", "<part>/boundary") and the named surfaces' ("envelope/sensor", ...).
inline constexpr const char* kPinBoreSet = "rig/pin_bore";      // pin_nodes
inline constexpr const char* kGuideSet = "rig/guide";           // guide_nodes
inline constexpr const char* kImpactorSet = "rig/impactor";     // impactor_nodes
inline constexpr const char* kDriveSurface = "carriage/drive";  // drive_surface

struct RigModelRequest {
  ImpactorKind impactor = ImpactorKind::rigid;
  ArtifactKind artifact = ArtifactKind::fixed;
  double gap = 0.01;                       // m, rod tip to envelope along the track at t = 0
  double mesh_scale = 1.0;                 // every mesh size times this
  std::optional<double> spring_stiffness;  // N/m: overrides cases.toml K_s (calibration)
};

// One part: its material (density tuned or given) and mass as meshed.
struct RigPart {
  std::string name;
  MaterialParams material;
  double mass = 0.0;  // kg, lumped
  std::string density_source;
  int elements = 0;
};

struct RigModel {
  Model model;  // bodies: carriage, rod[, spring], envelope, core_upper, core_lower
  std::vector<RigPart> parts;
  ImpactorKind impactor = ImpactorKind::rigid;
  ArtifactKind artifact = ArtifactKind::fixed;

  Vec3 track = Vec3::UnitY();     // the impactor's direction of travel
  Vec3 pin_point = Vec3::Zero();  // centre of rotation
  Vec3 pin_axis = Vec3::UnitX();
  std::vector<int> pin_nodes;       // the bore's surface: fixed (Fixed) or on the pin (Free)
  std::vector<int> guide_nodes;     // held to the track (thesis Fig. 3-18)
  std::vector<int> impactor_nodes;  // every node of the impactor's parts
  std::vector<int> artifact_nodes;
  std::vector<Triangle> drive_surface;        // the carriage's front face (thesis Fig. 3-16)
  std::vector<std::string> contact_surfaces;  // for the DCR: "rod/tip", "envelope/contact_zone"
  std::vector<int> sensor_nodes;              // the Pliance patch (eq. 3.8's Gamma_s)
  std::vector<Triangle> tip_face;             // the rod's flat tip (the sensor mat's one side)
  std::vector<Triangle> mat_footprint;        // the sensor's triangles the tip covers (its other)
  double sensor_mesh_area = 0.0;              // m^2, of its triangles
  int pearl_front = -1, pearl_back = -1;      // V_i (Fig. 3-6/3-20)
  int angle_node = -1;                        // theta_a (Fig. 3-21, eq. 3.7)

  double impactor_mass = 0.0;      // kg, lumped
  double artifact_mass = 0.0;      // kg
  double artifact_inertia = 0.0;   // kg m^2 about the pin axis
  double artifact_cm_depth = 0.0;  // m below the pin
  double spring_modulus = 0.0;     // Pa, eq. 3.1 (flexible)
  double spring_area = 0.0;        // m^2, meshed cross-section (volume / length)
  double spring_stiffness = 0.0;   // N/m, K_s used
  double rod_tip_y = 0.0;          // m, at t = 0
};

// Throws RigInputError naming the geometry file when the geometry and the case file disagree,
// std::invalid_argument when the densities cannot be tuned or the gap is not positive, and
// MeshError when Gmsh fails.
RigModel build_rig_model(const RigGeometry& geometry, const RigParameters& rig,
                         const RigModelRequest& request);

// E_s = K_s L / A   (thesis eq. 3.1) with A the meshed cross-section of the spring cylinder.
double spring_modulus_for(double stiffness, double length, double meshed_volume);

}  // namespace ccm::rig
