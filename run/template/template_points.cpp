#include "run/template/template_points.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <sstream>

#include "config/config_error.hpp"
#include "config/strict_table.hpp"
#include "config/text_file.hpp"
#include "run/compare/rigid_variant.hpp"
#include "run/compare/scene_groups.hpp"
#include "run/scene/scene_builder.hpp"
#include "run/scene/scene_file.hpp"
#include "run/scene/scene_inputs.hpp"
#include "run/template/scene_paths.hpp"
#include "study/grid/grid_expand.hpp"

namespace ccm::study {
namespace {

const SceneTemplate& scene_template(const GridSpec& spec) {
  if (!spec.scene_template) throw std::logic_error("the grid is not over a scene");
  return *spec.scene_template;
}

std::string template_text(const SceneTemplate& t) { return read_config_text(t.scene); }

// The point's values at their paths: other_axes "axes.<path>" and "levels.<path>".
void set_point_values(toml::table& doc, const GridPoint& point) {
  for (const auto& [name, value] : point.other_axes) {
    const std::string_view path = std::string_view(name).substr(
        name.starts_with(kTemplateAxisPrefix) ? kTemplateAxisPrefix.size()
                                              : kTemplateLevelPrefix.size());
    set_number_at_path(doc, path, value);
  }
}

std::string point_text(const toml::table& template_doc, const GridPoint& point) {
  toml::table doc = template_doc;
  set_point_values(doc, point);
  return document_text(doc);
}

ConfigError grid_error(const GridSpec& spec, int line, std::string_view key,
                       std::string_view problem) {
  return config_error(spec.source, line, key, problem);
}

// Every path leads to a number of the template, and each value alone gives a scene the scene
// reader accepts.
void check_axes(const GridSpec& spec, const toml::table& doc, std::string_view table,
                const std::vector<TemplateAxis>& axes) {
  for (const TemplateAxis& a : axes) {
    const std::string key = fmt::format("{}.\"{}\"", table, a.path);
    if (!number_at_path(doc, a.path))
      throw grid_error(
          spec, a.line, key,
          fmt::format("{} ({})", path_problem(doc, a.path), scene_template(spec).scene.string()));
    for (const double v : a.values) {
      toml::table one = doc;
      try {
        set_number_at_path(one, a.path, v);
        const std::filesystem::path& scene = scene_template(spec).scene;
        parse_scene(document_text(one),
                    scene.parent_path() / (scene.stem().string() + ".with-axis-value.toml"));
      } catch (const std::exception& e) {
        throw grid_error(spec, a.line, key,
                         fmt::format("the value {} gives a scene ccm refuses: {}", v, e.what()));
      }
    }
  }
}

Scene parsed_template(const GridSpec& spec) {
  const SceneTemplate& t = scene_template(spec);
  Scene scene;
  try {
    scene = parse_scene_file(t.scene);
  } catch (const ConfigError& e) {
    throw grid_error(spec, t.scene_line, "template.scene", e.what());
  }
  return scene;
}

void check_rigid(const GridSpec& spec, const Scene& scene) {
  const SceneTemplate& t = scene_template(spec);
  try {
    with_rigid_bodies(scene, t.rigid);
  } catch (const RigidVariantError& e) {
    throw grid_error(spec, t.rigid_line, "template.rigid", e.what());
  }
}

// A group to 12 significant digits: 0.5 * 3.6e-5 * 1.0 is stored, printed and asked for as
// 1.8e-05, not 1.7999999999999997e-05 (a level's value is a key of the fits).
double twelve_digits(double x) { return std::stod(fmt::format("{:.12g}", x)); }

}  // namespace

void derive_template_groups(const GridSpec& spec, GridPoint& point) {
  const SceneTemplate& t = scene_template(spec);
  const Scene scene = parse_scene(template_point_text(spec, point),
                                  template_point_name(spec, point, ImpactModel::ccm));
  const GroupsOrReason g = scene_groups(scene, build_model(scene), t.rigid, std::nullopt);
  if (!g.groups)
    throw grid_error(spec, t.rigid_line, "template.rigid",
                     fmt::format("point {}: {}", point.index, g.reason));
  point.modulus_ratio = twelve_digits(g.groups->modulus_ratio);
  point.length_ratio = twelve_digits(g.groups->length_ratio);
  point.kinetic_energy = twelve_digits(g.groups->kinetic_energy);
}

std::vector<GridPoint> template_grid_points(const GridSpec& spec) {
  const SceneTemplate& t = scene_template(spec);
  const Scene scene = parsed_template(spec);
  check_rigid(spec, scene);
  const toml::table doc = parse_toml(template_text(t), t.scene);
  check_axes(spec, doc, "axes", t.axes);
  check_axes(spec, doc, "levels", t.levels);
  std::vector<GridPoint> points = expand_grid(spec);
  for (GridPoint& p : points) derive_template_groups(spec, p);
  return points;
}

std::string template_point_text(const GridSpec& spec, const GridPoint& point) {
  const SceneTemplate& t = scene_template(spec);
  return point_text(parse_toml(template_text(t), t.scene), point);
}

std::string template_run_identity(const GridSpec& spec, const GridPoint& point, ImpactModel model) {
  const std::string text = template_point_text(spec, point);
  std::string all =
      scene_inputs_text(text, parse_scene(text, template_point_name(spec, point, model)));
  if (model == ImpactModel::rigid)
    all += fmt::format("\n#rigid {}\n", fmt::join(scene_template(spec).rigid, ","));
  return all;
}

std::filesystem::path template_point_name(const GridSpec& spec, const GridPoint& point,
                                          ImpactModel model) {
  const std::filesystem::path& scene = scene_template(spec).scene;
  return scene.parent_path() /
         fmt::format("{}.point{}.{}.toml", scene.stem().string(), point.index, to_string(model));
}

Scene template_point_scene(const GridSpec& spec, const GridPoint& point, ImpactModel model) {
  Scene scene =
      parse_scene(template_point_text(spec, point), template_point_name(spec, point, model));
  if (model == ImpactModel::rigid) scene = with_rigid_bodies(scene, scene_template(spec).rigid);
  scene.output.kinetic_energy = true;
  scene.output.displacement = true;
  return scene;
}

std::string template_artifact(const GridSpec& spec, const Scene& scene) {
  const std::vector<std::string>& rigid = scene_template(spec).rigid;
  for (const BodySpec& b : scene.bodies)
    if (!b.rigid && std::find(rigid.begin(), rigid.end(), b.name) == rigid.end()) return b.name;
  throw std::logic_error("a template scene without a deformable body passed its checks");
}

}  // namespace ccm::study
