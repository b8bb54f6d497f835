// The scene of a study's run, whichever kind of grid the study is: the thesis's sphere on a plate
// (run/scene/point_scene.hpp) or a grid over the user's own scene (run/template/
// template_points.hpp). Every command that runs or shows a study's runs goes through here.
#pragma once

#include <string>
#include <vector>

#include "records/grid_point.hpp"
#include "run/scene/scene.hpp"
#include "study/grid/grid_spec.hpp"

namespace ccm::study {

// The grid's points (expand_grid; a template's with their groups derived, after its checks) and
// its convergence runs (expand_convergence).
struct StudyPoints {
  std::vector<GridPoint> grid, convergence;
};
StudyPoints study_points(const GridSpec& spec);

// A point of the study moved along `axis` ("ER", or a template's "axes.<path>") to `value`, with
// the next free index; a template's point gets its groups from its scene again.
GridPoint moved_point(const GridSpec& spec, GridPoint point, const std::string& axis, double value,
                      int index);

// What identifies the run (hashed: runs with the same identity are run once).
std::string study_run_identity(const GridSpec& spec, const GridPoint& point, ImpactModel model);

// The scene file text `ccm study scene` prints for the run.
std::string study_scene_text(const GridSpec& spec, const GridPoint& point, ImpactModel model);

// The run's scene, parsed (and for a template's rigid model, with its bodies made rigid).
Scene study_scene(const GridSpec& spec, const GridPoint& point, ImpactModel model);

// The body whose kinetic energy, u_mean and u_max are the point's histories.
std::string study_artifact(const GridSpec& spec, const Scene& scene);

// The impactor: the thesis grid's sphere, or the template's body made rigid in the rigid model.
std::string study_impactor(const GridSpec& spec);

}  // namespace ccm::study
