// The scene of one grid point for one model (thesis 2.8): an artifact plate L_A x L_A x T_A
// (its bottom face fixed, or its x-edges clamped) struck on the middle of its top face by a
// sphere of diameter D_I moving along -z at v_I = sqrt(2 KE_I / m_I), its lowest point v_I t_c
// above the plate, so that contact starts at t_c.
//   ccm:   the sphere is a meshed Neo-Hookean body ("impactor"), contact model dcr;
//   rigid: the sphere is analytic ([contact.sphere] "impactor"), contact model rigid_penalty.
// Both models mesh the artifact identically and sample at the same output times.
#pragma once

#include <filesystem>
#include <string>

#include "records/grid_point.hpp"
#include "run/scene/scene.hpp"
#include "study/grid/grid_spec.hpp"

namespace ccm::study {

inline constexpr const char* kArtifactBody = "artifact";
inline constexpr const char* kImpactorName = "impactor";

// The canonical scene file text of the point (docs/scene-file.md): deterministic, every number
// in shortest round-trip form, independent of the point's index. Runs unchanged with `ccm run`.
std::string point_scene_text(const GridSpec& spec, const GridPoint& point, ImpactModel model);

// The name the scene goes by in messages: "<grid folder>/<grid stem>.point<index>.<model>.toml".
std::filesystem::path point_scene_name(const GridSpec& spec, const GridPoint& point,
                                       ImpactModel model);

// point_scene_text parsed by the scene parser (so it is checked exactly like a scene file).
Scene point_scene(const GridSpec& spec, const GridPoint& point, ImpactModel model);

}  // namespace ccm::study
