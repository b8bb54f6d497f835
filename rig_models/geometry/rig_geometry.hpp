// The rig's geometry for the simulations (rig_models/geometry.toml): every dimension, material
// and mesh size with its source. Frame: origin at the centre of the pin, x along the pin axis,
// y along the impactor's travel (toward the artifact), z up.
#pragma once

#include <filesystem>
#include <optional>

#include "rig_models/cases/rig_case.hpp"

namespace ccm::rig {

struct ArtifactGeometry {
  SourcedValue envelope_outer_diameter, envelope_wall, envelope_top, envelope_length;
  SourcedValue core_width, core_top, core_bottom, core_split;
  SourcedValue stabilizer_thickness, stabilizer_upper_depth, stabilizer_lower_depth;
  SourcedValue pin_diameter;
  SourcedValue sensor_width, sensor_height, contact_zone;
  SourcedValue angle_node_depth;
};

struct ImpactorGeometry {
  SourcedValue rod_diameter, rod_length, guide_length;
  SourcedValue carriage_width, carriage_length, carriage_height;
  SourcedValue spring_mass;
  SourcedValue pearl_inset;
};

// A part's material; rho is absent where it is tuned (carriage, core) or derived (spring), E
// where it is derived (spring, eq. 3.1).
struct PartMaterial {
  std::optional<SourcedValue> E, nu, rho;
};

struct RigMaterials {
  PartMaterial envelope, rod, carriage, core, spring;
};

struct MeshSizes {
  SourcedValue carriage, rod, spring, envelope, envelope_contact, core;
};

struct ContactSettings {
  SourcedValue friction;     // Coulomb mu between rod and envelope
  SourcedValue restitution;  // the DCR pair's coefficient, in [0, 1]
};

struct RigGeometry {
  std::filesystem::path source;
  ArtifactGeometry artifact;
  ImpactorGeometry impactor;
  RigMaterials materials;
  MeshSizes mesh;
  ContactSettings contact;
  SourcedValue gravity;  // m/s^2, along -z
};

}  // namespace ccm::rig
