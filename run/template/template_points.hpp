// The points of a grid over a scene (study/grid/grid_spec.hpp, SceneTemplate; docs/grid-file.md,
// "Grids over your own scene"): each point's scene is the template with the point's axis values
// set at their paths; the "ccm" model runs it as written, the "rigid" model with the template's
// rigid bodies made rigid (run/compare/rigid_variant.hpp). A point's ER, RLS and KE are that
// scene's groups (run/compare/scene_groups.hpp), so the fits, the decision rule and the report
// read a template study as they read the thesis grid.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "records/grid_point.hpp"
#include "run/scene/scene.hpp"
#include "study/grid/grid_spec.hpp"

namespace ccm::study {

// Every point of the grid (expand_grid's order and indices) with its groups derived, after
// checking everything a run would refuse: the template scene, each path (nearest valid path when
// it leads to no number), each axis value (the scene reader's check), the rigid bodies, and that
// each point's scene has one impactor and one artifact. Throws ConfigError naming the grid file,
// the line and the key; meshes each point's scene once (the groups need its masses).
std::vector<GridPoint> template_grid_points(const GridSpec& spec);

// Sets the point's ER, RLS and KE from its scene's groups (to 12 significant digits). Throws
// ConfigError naming the grid file's `rigid` line when the scene has no impactor or artifact.
void derive_template_groups(const GridSpec& spec, GridPoint& point);

// The point's scene text: the template's with the point's values set (TOML, as toml++ writes it).
std::string template_point_text(const GridSpec& spec, const GridPoint& point);

// What identifies the run: the text, the mesh files it reads and, for the rigid model, the bodies
// made rigid.
std::string template_run_identity(const GridSpec& spec, const GridPoint& point, ImpactModel model);

// "<template folder>/<template stem>.point<index>.<model>.toml": relative mesh paths resolve as in
// the template.
std::filesystem::path template_point_name(const GridSpec& spec, const GridPoint& point,
                                          ImpactModel model);

// The point's scene for the model, with kinetic energy and displacement histories switched on
// (the metrics read them).
Scene template_point_scene(const GridSpec& spec, const GridPoint& point, ImpactModel model);

// The body whose histories give the metrics: the one that stays deformable in the rigid model.
std::string template_artifact(const GridSpec& spec, const Scene& scene);

}  // namespace ccm::study
