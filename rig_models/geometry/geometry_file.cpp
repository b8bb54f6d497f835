#include "rig_models/geometry/geometry_file.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <utility>

#include "config/strict_table.hpp"
#include "rig_models/cases/sourced_value.hpp"
#include "rig_models/core/rig_error.hpp"

namespace ccm::rig {
namespace {

namespace fs = std::filesystem;

SourcedValue length(const StrictTable& t, std::string_view key) {
  return read_sourced(t, key, "m");
}

ArtifactGeometry read_artifact(const StrictTable& root) {
  const StrictTable t = root.need_table("artifact");
  t.allow_only({"envelope_outer_diameter", "envelope_wall", "envelope_top", "envelope_length",
                "core_width", "core_top", "core_bottom", "core_split", "stabilizer_thickness",
                "stabilizer_upper_depth", "stabilizer_lower_depth", "pin_diameter", "sensor_width",
                "sensor_height", "contact_zone", "angle_node_depth"});
  ArtifactGeometry a;
  a.envelope_outer_diameter = length(t, "envelope_outer_diameter");
  a.envelope_wall = length(t, "envelope_wall");
  a.envelope_top = length(t, "envelope_top");
  a.envelope_length = length(t, "envelope_length");
  a.core_width = length(t, "core_width");
  a.core_top = length(t, "core_top");
  a.core_bottom = length(t, "core_bottom");
  a.core_split = length(t, "core_split");
  a.stabilizer_thickness = length(t, "stabilizer_thickness");
  a.stabilizer_upper_depth = length(t, "stabilizer_upper_depth");
  a.stabilizer_lower_depth = length(t, "stabilizer_lower_depth");
  a.pin_diameter = length(t, "pin_diameter");
  a.sensor_width = length(t, "sensor_width");
  a.sensor_height = length(t, "sensor_height");
  a.contact_zone = length(t, "contact_zone");
  a.angle_node_depth = length(t, "angle_node_depth");
  const double r_in = a.envelope_outer_diameter.value / 2 - a.envelope_wall.value;
  if (!(r_in > 0.0))
    t.fail("envelope_wall", "must be less than half the envelope's outer diameter");
  if (!(a.core_width.value / std::sqrt(2.0) < r_in))
    t.fail("core_width", fmt::format("the core's corners must lie inside the envelope's bore "
                                     "(half-diagonal {:.4g} m, bore radius {:.4g} m)",
                                     a.core_width.value / std::sqrt(2.0), r_in));
  if (!(a.pin_diameter.value < a.core_width.value))
    t.fail("pin_diameter", "the pin's bore must fit inside the core");
  if (!(a.core_top.value < a.envelope_top.value))
    t.fail("core_top", "the core must end inside the envelope (core_top < envelope_top)");
  const double envelope_bottom = a.envelope_length.value - a.envelope_top.value;
  if (!(a.core_bottom.value < envelope_bottom))
    t.fail("core_bottom", fmt::format("the core must end inside the envelope (< {:.4g} m below "
                                      "the pin)",
                                      envelope_bottom));
  if (!(a.pin_diameter.value / 2 < a.core_top.value))
    t.fail("core_top", "the pin's bore must lie inside the core");
  if (!(a.core_split.value > a.pin_diameter.value / 2 && a.core_split.value < a.core_bottom.value))
    t.fail("core_split", "must lie between the pin and the core's bottom");
  for (const auto& [key, depth] :
       {std::pair{"stabilizer_upper_depth", &a.stabilizer_upper_depth},
        std::pair{"stabilizer_lower_depth", &a.stabilizer_lower_depth}}) {
    const double d = depth->value;
    const double half = a.stabilizer_thickness.value / 2;
    if (!(d - half > a.pin_diameter.value / 2 && d + half < a.core_bottom.value))
      t.fail(key, "the stabilizer must sit on the core, below the pin");
    if (std::abs(d - a.core_split.value) < half)
      t.fail(key, "the stabilizer must not straddle the core's split");
  }
  if (!(a.stabilizer_upper_depth.value + a.stabilizer_thickness.value <
        a.stabilizer_lower_depth.value))
    t.fail("stabilizer_lower_depth", "must lie below the upper stabilizer");
  if (!(a.angle_node_depth.value <= a.core_bottom.value))
    t.fail("angle_node_depth", "must lie on the core (at most core_bottom below the pin)");
  return a;
}

ImpactorGeometry read_impactor(const StrictTable& root) {
  const StrictTable t = root.need_table("impactor");
  t.allow_only({"rod_diameter", "rod_length", "guide_length", "carriage_width", "carriage_length",
                "carriage_height", "spring_mass", "pearl_inset"});
  ImpactorGeometry g;
  g.rod_diameter = length(t, "rod_diameter");
  g.rod_length = length(t, "rod_length");
  g.guide_length = length(t, "guide_length");
  g.carriage_width = length(t, "carriage_width");
  g.carriage_length = length(t, "carriage_length");
  g.carriage_height = length(t, "carriage_height");
  g.spring_mass = read_sourced(t, "spring_mass", "kg");
  g.pearl_inset = length(t, "pearl_inset");
  if (!(g.guide_length.value < g.rod_length.value))
    t.fail("guide_length", "must be shorter than the rod");
  if (!(g.rod_diameter.value < std::min(g.carriage_width.value, g.carriage_height.value)))
    t.fail("rod_diameter", "the rod must fit the carriage's front face");
  if (!(2 * g.pearl_inset.value < g.carriage_length.value))
    t.fail("pearl_inset", "the two pearls must lie on the carriage's top face");
  return g;
}

// One part's material: E, nu and rho as `keys` says ("E", "nu", "rho" in any subset).
PartMaterial read_material(const StrictTable& materials, std::string_view part,
                           std::initializer_list<std::string_view> keys) {
  const StrictTable t = materials.need_table(part);
  t.allow_only(keys);
  PartMaterial m;
  for (std::string_view key : keys) {
    if (key == "E") m.E = read_sourced(t, "E", "Pa");
    if (key == "rho") m.rho = read_sourced(t, "rho", "kg/m^3");
    if (key == "nu") {
      m.nu = read_sourced(t, "nu", "1", {0.0, false});
      if (!(m.nu->value < 0.5)) t.fail("nu", fmt::format("must be < 0.5 (got {})", m.nu->value));
    }
  }
  return m;
}

RigMaterials read_materials(const StrictTable& root) {
  const StrictTable t = root.need_table("materials");
  t.allow_only({"envelope", "rod", "carriage", "core", "spring"});
  RigMaterials m;
  m.envelope = read_material(t, "envelope", {"E", "nu", "rho"});
  m.rod = read_material(t, "rod", {"E", "nu", "rho"});
  m.carriage = read_material(t, "carriage", {"E", "nu"});
  m.core = read_material(t, "core", {"E", "nu"});
  m.spring = read_material(t, "spring", {"nu"});
  return m;
}

MeshSizes read_mesh(const StrictTable& root, const ArtifactGeometry& a, const ImpactorGeometry& g) {
  const StrictTable t = root.need_table("mesh");
  t.allow_only({"carriage", "rod", "spring", "envelope", "envelope_contact", "core"});
  MeshSizes m{length(t, "carriage"),         length(t, "rod"),
              length(t, "spring"),           length(t, "envelope"),
              length(t, "envelope_contact"), length(t, "core")};
  // Gmsh cannot mesh a curved face with elements wider than its radius.
  if (m.rod.value > g.rod_diameter.value / 2 * 1.0001)
    t.fail("rod", "must not exceed the rod's radius");
  if (m.envelope_contact.value > m.envelope.value)
    t.fail("envelope_contact", "must not exceed the envelope's size away from the contact");
  if (m.envelope_contact.value > a.contact_zone.value / 2)
    t.fail("envelope_contact", "must be smaller than half the contact zone");
  return m;
}

}  // namespace

RigGeometry parse_geometry(std::string_view text, const fs::path& source) {
  toml::table root;
  try {
    root = toml::parse(text, source.string());
  } catch (const toml::parse_error& e) {
    throw rig_input_error(source, static_cast<int>(e.source().begin.line), "", e.description());
  }
  const StrictTable fields(root, "", source);
  fields.allow_only({"artifact", "impactor", "materials", "mesh", "contact", "environment"});
  RigGeometry g;
  g.source = source;
  g.artifact = read_artifact(fields);
  g.impactor = read_impactor(fields);
  g.materials = read_materials(fields);
  g.mesh = read_mesh(fields, g.artifact, g.impactor);
  const StrictTable contact = fields.need_table("contact");
  contact.allow_only({"friction", "restitution"});
  g.contact.friction = read_sourced(contact, "friction", "1", {0.0, false});
  g.contact.restitution = read_sourced(contact, "restitution", "1", {0.0, false});
  if (g.contact.restitution.value > 1.0)
    contact.fail("restitution",
                 fmt::format("must be at most 1 (got {})", g.contact.restitution.value));
  const StrictTable env = fields.need_table("environment");
  env.allow_only({"gravity"});
  g.gravity = read_sourced(env, "gravity", "m/s^2", {0.0, false});
  return g;
}

RigGeometry read_geometry(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw rig_input_error(file, 0, "", "cannot open the file for reading");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_geometry(text.str(), file);
}

void fit_sensor_patch(RigGeometry& geometry, double area) {
  ArtifactGeometry& a = geometry.artifact;
  const double scale = std::sqrt(area / (a.sensor_width.value * a.sensor_height.value));
  if (std::abs(scale - 1.0) < 1e-12) return;
  const std::string why = fmt::format("; scaled by {:.6g} to the trials' sensor area", scale);
  a.sensor_width.value *= scale;
  a.sensor_width.source += why;
  a.sensor_height.value *= scale;
  a.sensor_height.source += why;
}

void check_against_cases(const RigGeometry& geometry, const RigParameters& rig) {
  const ArtifactGeometry& a = geometry.artifact;
  const double depth = rig.pivot_to_sensor.value;
  const double envelope_bottom = a.envelope_length.value - a.envelope_top.value;
  const double reach = std::max(a.sensor_height.value, a.contact_zone.value) / 2;
  auto fail = [&](std::string_view key, const std::string& problem) {
    throw rig_input_error(geometry.source, 0, key, problem);
  };
  if (!(depth - reach > 0.0 && depth + reach < envelope_bottom))
    fail("artifact.contact_zone",
         fmt::format("the contact zone around the contact point {} m below the pin (cases.toml "
                     "pivot_to_sensor) must lie on the envelope, below the pin",
                     depth));
  const double area = a.sensor_width.value * a.sensor_height.value;
  if (std::abs(area - rig.sensor_area.value) > 0.01 * rig.sensor_area.value)
    fail("artifact.sensor_width",
         fmt::format("the sensor patch is {:.4g} m^2, cases.toml sensor_area is {:.4g} m^2", area,
                     rig.sensor_area.value));
  if (a.sensor_width.value > 0.5 * std::acos(-1.0) * a.envelope_outer_diameter.value / 2)
    fail("artifact.sensor_width",
         fmt::format("the sensor patch ({:.4g} m wide) must fit on the struck half of the "
                     "envelope ({:.4g} m of arc)",
                     a.sensor_width.value,
                     0.5 * std::acos(-1.0) * a.envelope_outer_diameter.value / 2));
}

}  // namespace ccm::rig
