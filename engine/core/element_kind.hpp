// Which element formulation a body's tets use (docs/elements.md). A header of its own so that
// scene specifications can name the kind without the element kernels.
#pragma once

#include <array>
#include <string_view>

namespace ccm {

enum class ElementKind {
  tet4,           // the plain linear tet: one constant pressure per element (locks at nu -> 0.5)
  nodal_pressure  // averaged nodal pressure (Bonet & Burton 1998): volumetric energy at nodes
};

inline constexpr std::array<std::string_view, 2> kElementKindNames = {"tet4", "nodal_pressure"};

// The one default for the engine and the scene file.
inline constexpr ElementKind kDefaultElementKind = ElementKind::tet4;

constexpr std::string_view to_string(ElementKind kind) {
  return kElementKindNames[kind == ElementKind::nodal_pressure ? 1 : 0];
}

// False (and `out` unchanged) for a name that is not in kElementKindNames.
constexpr bool parse_element_kind(std::string_view name, ElementKind& out) {
  for (const ElementKind k : {ElementKind::tet4, ElementKind::nodal_pressure})
    if (name == to_string(k)) {
      out = k;
      return true;
    }
  return false;
}

}  // namespace ccm
