#include "run/runner/study_scene.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "run/scene/point_scene.hpp"
#include "run/template/template_points.hpp"
#include "study/grid/grid_expand.hpp"
#include "study/refine/boundary_refinement.hpp"

namespace ccm::study {

StudyPoints study_points(const GridSpec& spec) {
  return {spec.scene_template ? template_grid_points(spec) : expand_grid(spec),
          expand_convergence(spec)};
}

GridPoint moved_point(const GridSpec& spec, GridPoint point, const std::string& axis, double value,
                      int index) {
  point.index = index;
  set_axis_coordinate(point, axis, value);
  if (spec.scene_template) derive_template_groups(spec, point);
  return point;
}

std::string study_run_identity(const GridSpec& spec, const GridPoint& point, ImpactModel model) {
  return spec.scene_template ? template_run_identity(spec, point, model)
                             : point_scene_text(spec, point, model);
}

std::string study_scene_text(const GridSpec& spec, const GridPoint& point, ImpactModel model) {
  if (!spec.scene_template) return point_scene_text(spec, point, model);
  std::string text = template_point_text(spec, point);
  if (model == ImpactModel::rigid)
    text = fmt::format(
        "# The rigid model of this point is this scene with {0} made rigid: saved as FILE,\n"
        "# `ccm compare FILE --rigid {0}` runs it beside the scene as written.\n{1}",
        fmt::join(spec.scene_template->rigid, ","), text);
  return text;
}

Scene study_scene(const GridSpec& spec, const GridPoint& point, ImpactModel model) {
  return spec.scene_template ? template_point_scene(spec, point, model)
                             : point_scene(spec, point, model);
}

std::string study_artifact(const GridSpec& spec, const Scene& scene) {
  return spec.scene_template ? template_artifact(spec, scene) : kArtifactBody;
}

std::string study_impactor(const GridSpec& spec) {
  return spec.scene_template ? spec.scene_template->rigid.front() : kImpactorName;
}

}  // namespace ccm::study
