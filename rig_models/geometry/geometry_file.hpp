// Reading the rig's geometry file (rig_models/geometry.toml) into a typed, checked RigGeometry:
// every key required, no unknown key, every parameter { value, unit, source } with the unit
// expected, lengths > 0, and the dimensions consistent with one another (the core inside the
// envelope, the stabilizers on the core, the sensor and the contact point on the envelope).
// Failures are RigInputError "<file>:<line>: <key path>: <problem>".
#pragma once

#include <filesystem>
#include <string_view>

#include "rig_models/geometry/rig_geometry.hpp"

namespace ccm::rig {

RigGeometry parse_geometry(std::string_view text, const std::filesystem::path& source);
RigGeometry read_geometry(const std::filesystem::path& file);

// Scales the sensor patch (artifact.sensor_width and sensor_height, its aspect kept) to `area`
// [m^2]: a trial folder's rig file may give its own sensor area (trial_rig_file.hpp).
void fit_sensor_patch(RigGeometry& geometry, double area);

// The checks that involve the case file too: the contact point (cases.toml pivot_to_sensor)
// must lie on the envelope, below the core's split and within the sensor's reach of the lower
// stabilizer's plane, and the sensor patch's area must be cases.toml sensor_area (1 %).
// Throws RigInputError naming the geometry file and the key.
void check_against_cases(const RigGeometry& geometry, const RigParameters& rig);

}  // namespace ccm::rig
