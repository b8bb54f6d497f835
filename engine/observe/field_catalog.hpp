// The fields a run can write for a post-processor (docs/fields.md): their names as a scene file
// spells them, their units and where they live (nodes, tets, boundary triangles). Names only:
// the values are computed and written by io/fields/ (HDF5 stays out of the engine).
#pragma once

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

namespace ccm {

enum class FieldKind { displacement, velocity, J, von_mises, contact_pressure, body_id };

// Where a field's values sit: one per node, one per tet, one per boundary triangle.
enum class FieldCentre { node, tet, face };

struct FieldInfo {
  FieldKind kind;
  std::string_view name;  // as in `[output] fields = [...]` and in the XDMF file
  std::string_view unit;  // SI; "-" for a pure number
  FieldCentre centre;
  int components;  // 3: a vector, 1: a scalar
  std::string_view meaning;
};

inline constexpr std::array<FieldInfo, 6> kFieldCatalog{{
    {FieldKind::displacement, "displacement", "m", FieldCentre::node, 3, "u = x - X"},
    {FieldKind::velocity, "velocity", "m/s", FieldCentre::node, 3, "v"},
    {FieldKind::J, "J", "-", FieldCentre::tet, 1, "volume ratio det F"},
    {FieldKind::von_mises, "von_mises", "Pa", FieldCentre::tet, 1,
     "von Mises equivalent of the Cauchy stress"},
    {FieldKind::contact_pressure, "contact_pressure", "Pa", FieldCentre::face, 1,
     "normal contact pressure on boundary triangles (compressive positive)"},
    {FieldKind::body_id, "body_id", "-", FieldCentre::tet, 1,
     "index of the body in the scene, from 0"},
}};

inline const FieldInfo& field_info(FieldKind kind) {
  for (const FieldInfo& f : kFieldCatalog)
    if (f.kind == kind) return f;
  return kFieldCatalog[0];  // unreachable: every kind is in the catalogue
}

inline std::optional<FieldKind> parse_field_name(std::string_view name) {
  for (const FieldInfo& f : kFieldCatalog)
    if (f.name == name) return f.kind;
  return std::nullopt;
}

// Every name, in catalogue order (for messages and `--fields`).
inline constexpr std::array<std::string_view, kFieldCatalog.size()> field_names() {
  std::array<std::string_view, kFieldCatalog.size()> names{};
  for (size_t i = 0; i < kFieldCatalog.size(); ++i) names[i] = kFieldCatalog[i].name;
  return names;
}

// Field frames fall on output samples: the field interval must be a whole multiple (>= 1) of the
// output interval. Empty when it is, else the problem ("must be a whole multiple ...").
inline std::string field_interval_problem(double field_interval, double output_interval) {
  const double ratio = field_interval / output_interval;
  if (field_interval > 0.0 && ratio >= 1.0 - 1e-9 &&
      std::abs(ratio - std::round(ratio)) <= 1e-9 * ratio)
    return {};
  return fmt::format("must be a whole multiple of the output interval {} s (got {} s)",
                     output_interval, field_interval);
}

}  // namespace ccm
