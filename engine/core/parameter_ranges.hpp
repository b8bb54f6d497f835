// The allowed range of every parameter that more than one reader checks: scene files
// (run/scene/scene_file.cpp), grid files (study/grid/) and the engine's own constructors. Written
// once here, so a value a scene accepts is a value a grid and the engine accept, and each message
// states the same interval.
#pragma once

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <string>

namespace ccm {

struct ParameterRange {
  double lo = 0.0, hi = std::numeric_limits<double>::infinity();
  bool lo_closed = true, hi_closed = false;

  bool contains(double v) const {
    return std::isfinite(v) && (lo_closed ? v >= lo : v > lo) && (hi_closed ? v <= hi : v < hi);
  }
  // "must lie in (0, 2] (got 3)"; "must be >= 0 (got -1)" for a half-line.
  std::string problem(double v) const {
    if (contains(v)) return {};
    if (std::isinf(hi)) return fmt::format("must be {} {} (got {})", lo_closed ? ">=" : ">", lo, v);
    return fmt::format("must lie in {}{}, {}{} (got {})", lo_closed ? "[" : "(", lo, hi,
                       hi_closed ? "]" : ")", v);
  }
};

// dt_safety: the one safety factor on the stable step (step_safety.hpp). A scene may go beyond 1
// for stability experiments (it then warns); a study's grid may not (its runs are results).
inline constexpr ParameterRange kDtSafetyRange{0.0, 2.0, false, true};
inline constexpr ParameterRange kStudyDtSafetyRange{0.0, 1.0, false, true};
// Contact: the pair coefficient of restitution e, Coulomb's mu, the dashpots' zeta.
inline constexpr ParameterRange kRestitutionRange{0.0, 1.0, true, true};
inline constexpr ParameterRange kFrictionRange{0.0, std::numeric_limits<double>::infinity(), true,
                                               false};
inline constexpr ParameterRange kDampingRange{0.0, std::numeric_limits<double>::infinity(), true,
                                              false};
// A smoothed rigid surface's crease angle [degrees] (engine/contact/penalty/curved_surface.hpp).
inline constexpr ParameterRange kCreaseAngleRange{0.0, 180.0, true, false};
// A pin's clamp (engine/bc/pin_joint.hpp, PJ.1): torsional stiffness and damping.
inline constexpr ParameterRange kClampRange{0.0, std::numeric_limits<double>::infinity(), true,
                                            false};
// A track's friction (engine/bc/track_friction.hpp): the normal force and the viscous damping.
inline constexpr ParameterRange kNormalForceRange{0.0, std::numeric_limits<double>::infinity(),
                                                  true, false};
// Poisson's ratio of an isotropic solid.
inline constexpr ParameterRange kPoissonRange{-1.0, 0.5, false, false};

}  // namespace ccm
