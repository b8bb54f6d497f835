// How the rigid-sphere penalty model chooses its springs' stiffness
// (engine/contact/rigid_sphere_penalty.hpp; docs/contact-time-step.md "The element-scaled
// penalty"). A header of its own so that scene and grid specifications can name the mode
// without the model.
#pragma once

#include <array>
#include <string_view>

namespace ccm {

enum class PenaltyMode {
  per_point,  // K_P [N/m] at every quadrature point (thesis 2.8, eq. 2.5): the default
  element     // k_T = s K A^2 / V per surface triangle, k_T / 3 at each of its points
};

inline constexpr std::array<std::string_view, 2> kPenaltyModeNames = {"per_point", "element"};

constexpr std::string_view to_string(PenaltyMode mode) {
  return kPenaltyModeNames[mode == PenaltyMode::element ? 1 : 0];
}

// False (and `out` unchanged) for a name that is not in kPenaltyModeNames.
constexpr bool parse_penalty_mode(std::string_view name, PenaltyMode& out) {
  for (const PenaltyMode m : {PenaltyMode::per_point, PenaltyMode::element})
    if (name == to_string(m)) {
      out = m;
      return true;
    }
  return false;
}

// s of the element-scaled penalty: the one default for the engine, the scene file and the grid.
inline constexpr double kDefaultElementPenaltyScale = 0.1;

// K_P [N/m] per quadrature point of the per-point mode: the thesis's value (thesis 2.8).
inline constexpr double kDefaultPointPenalty = 1e6;

// A meshed rigid surface's crease angle [degrees] (engine/contact/penalty/curved_surface.hpp):
// edges whose faces turn by less are smoothed over, the rest stay sharp. 0 keeps every facet flat
// (the default: the surface as meshed, at the flat surface's cost); 45 smooths a sphere or
// cylinder meshed with 8 or more edges around and keeps a cube's edges.
inline constexpr double kDefaultCreaseAngle = 0.0;
// The trade-study grid's meshed rigid impactor's (study/grid/grid_spec.hpp): smoothed all over.
inline constexpr double kMeshedImpactorCreaseAngle = 45.0;

}  // namespace ccm
