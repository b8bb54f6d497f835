#include "study/grid/grid_file.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "config/config_error.hpp"
#include "config/did_you_mean.hpp"
#include "config/strict_table.hpp"
#include "config/text_file.hpp"
#include "engine/core/parameter_ranges.hpp"
#include "study/grid/point_parameters.hpp"

namespace ccm::study {
namespace {

double positive(const StrictTable& t, std::string_view key) {
  const double v = t.need_number(key);
  if (!(v > 0.0)) t.fail(key, fmt::format("must be > 0 (got {})", v));
  return v;
}

// The value of `key` (or `fallback` when absent), checked like the axis of the same meaning.
double checked_as_axis(const StrictTable& t, std::string_view key, std::string_view axis,
                       double fallback) {
  const double v = t.number_or(key, fallback);
  const std::string problem = axis_value_problem(axis, v);
  if (!problem.empty()) t.fail(key, problem);
  return v;
}

double poisson(const StrictTable& t, std::string_view key) {
  const double v = t.need_number(key);
  if (!kPoissonRange.contains(v)) t.fail(key, kPoissonRange.problem(v));
  return v;
}

// An axis: a non-empty array of distinct allowed values, kept in the file's order.
// `axis` names the range check (point_parameters.hpp), `key` the array.
std::vector<double> axis_values(const StrictTable& t, std::string_view key, std::string_view axis) {
  const std::vector<double> values = t.number_array(key);
  for (size_t i = 0; i < values.size(); ++i) {
    const std::string problem = axis_value_problem(axis, values[i]);
    if (!problem.empty()) t.fail(key, fmt::format("[{}] {}", i, problem));
    const auto earlier_end = values.begin() + static_cast<long>(i);
    if (std::find(values.begin(), earlier_end, values[i]) != earlier_end)
      t.fail(key, fmt::format("[{}] repeats the value {}", i, values[i]));
  }
  return values;
}

void parse_axes(const StrictTable& root, GridSpec& g) {
  const StrictTable t = root.need_table("axes");
  std::vector<std::string_view> allowed = {"ER", "RLS", "KE"};
  for (std::string_view n : other_axis_names()) allowed.push_back(n);
  t.allow_only(allowed);
  g.modulus_ratios = axis_values(t, "ER", "ER");
  g.length_ratios = axis_values(t, "RLS", "RLS");
  g.kinetic_energies = axis_values(t, "KE", "KE");
  for (std::string_view n : other_axis_names())
    if (t.has(n)) g.other_axes.emplace(std::string(n), axis_values(t, n, n));
}

void parse_time(const StrictTable& root, GridSpec& g) {
  const StrictTable t = root.need_table("time");
  t.allow_only(
      {"contact_time", "end", "output_interval", "dt_safety", "max_steps", "end_after_separation"});
  GridTime& time = g.time;
  time.end = positive(t, "end");
  time.contact_time = positive(t, "contact_time");
  if (time.contact_time >= time.end)
    t.fail("contact_time", fmt::format("must be < end = {} (got {})", time.end, time.contact_time));
  time.output_interval = positive(t, "output_interval");
  if (time.output_interval > time.end)
    t.fail("output_interval", fmt::format("must be <= end = {}", time.end));
  time.dt_safety = t.number_or("dt_safety", time.dt_safety);
  if (!kStudyDtSafetyRange.contains(time.dt_safety))
    t.fail("dt_safety", kStudyDtSafetyRange.problem(time.dt_safety));
  time.max_steps = t.integer("max_steps").value_or(0);
  if (time.max_steps < 0) t.fail("max_steps", "must be >= 0 (0: no limit)");
  if (t.has("end_after_separation")) {
    const double hold = t.number_or("end_after_separation", 0.0);
    if (!(hold >= 0.0) || hold >= time.end)
      t.fail("end_after_separation",
             fmt::format("must lie in [0, end = {}) (got {})", time.end, hold));
    time.end_after_separation = hold;
  }
}

ArtifactSupport parse_support(const StrictTable& t) {
  const std::string s = t.string("support").value_or("base");
  if (s == "base") return ArtifactSupport::base;
  if (s == "edges") return ArtifactSupport::edges;
  t.fail("support", fmt::format("must be \"base\" or \"edges\" (got \"{}\")", s));
}

// contact_mesh_size and contact_radius [m]: both or neither.
void parse_contact_zone(const StrictTable& t, double& mesh_size, double& radius) {
  const bool has_size = t.has("contact_mesh_size"), has_radius = t.has("contact_radius");
  if (has_size != has_radius)
    t.fail(has_size ? "contact_radius" : "contact_mesh_size",
           "contact_mesh_size and contact_radius are given together or not at all");
  if (!has_size) return;
  mesh_size = positive(t, "contact_mesh_size");
  radius = positive(t, "contact_radius");
}

void parse_artifact(const StrictTable& root, GridSpec& g) {
  const StrictTable t = root.need_table("artifact");
  t.allow_only({"length", "thickness", "E", "nu", "rho", "mesh_size", "contact_mesh_size",
                "contact_radius", "support"});
  ArtifactSpec& a = g.artifact;
  a.length = positive(t, "length");
  a.thickness = positive(t, "thickness");
  a.E = positive(t, "E");
  a.nu = poisson(t, "nu");
  a.rho = positive(t, "rho");
  a.mesh_size = positive(t, "mesh_size");
  parse_contact_zone(t, a.contact_mesh_size, a.contact_radius);
  if (a.contact_mesh_size > a.mesh_size)
    t.fail("contact_mesh_size", fmt::format("must not exceed mesh_size = {} (got {})", a.mesh_size,
                                            a.contact_mesh_size));
  a.support = parse_support(t);
}

void parse_impactor(const StrictTable& root, GridSpec& g) {
  const StrictTable t = root.need_table("impactor");
  t.allow_only({"nu", "rho", "mesh_size_ratio", "contact_mesh_size", "contact_radius"});
  g.impactor.nu = poisson(t, "nu");
  g.impactor.rho = positive(t, "rho");
  if (!t.has("mesh_size_ratio")) t.fail("mesh_size_ratio", "required key is missing");
  g.impactor.mesh_size_ratio = checked_as_axis(t, "mesh_size_ratio", "impactor_mesh_ratio", 0.0);
  parse_contact_zone(t, g.impactor.contact_mesh_size, g.impactor.contact_radius);
}

// The rigid model's springs: penalty_mode with penalty (per_point) or penalty_scale (element),
// or, with a penalty_scale axis, the axis alone (0: per point; docs/grid-file.md).
void parse_penalty(const StrictTable& t, GridSpec& g) {
  GridContact& c = g.contact;
  const bool scale_axis = g.other_axes.contains("penalty_scale");
  for (std::string_view key : {"penalty_mode", "penalty_scale"})
    if (scale_axis && t.has(key))
      t.fail(key,
             "the penalty_scale axis chooses the mode at every point (0: the per-point K_P, "
             "> 0: element); remove this key");
  if (const auto mode = t.string("penalty_mode");
      mode && !parse_penalty_mode(*mode, c.penalty_mode))
    t.fail("penalty_mode", unknown_value_problem(*mode, kPenaltyModeNames));
  const bool element = c.penalty_mode == PenaltyMode::element;
  if (element && t.has("penalty"))
    t.fail("penalty", "applies only with penalty_mode = \"per_point\"");
  if (!element && !scale_axis && t.has("penalty_scale"))
    t.fail("penalty_scale", "applies only with penalty_mode = \"element\"");
  const bool penalty_axis = g.other_axes.contains("penalty");
  if (penalty_axis && (element || scale_axis))
    t.fail(element ? "penalty_mode" : "",
           "a penalty (K_P) axis needs the per-point mode without a penalty_scale axis (the "
           "element mode does not use K_P: its points would repeat)");
  c.penalty = checked_as_axis(t, "penalty", "penalty", c.penalty);
  if (t.has("penalty_scale")) {
    c.penalty_scale = t.need_number("penalty_scale");
    if (!(c.penalty_scale > 0.0))
      t.fail("penalty_scale", fmt::format("must be > 0 (got {})", c.penalty_scale));
  }
}

void parse_contact(const StrictTable& root, GridSpec& g) {
  const auto t = root.table("contact");
  if (!t) {
    if (g.other_axes.contains("penalty") && g.other_axes.contains("penalty_scale"))
      root.fail("axes", "a penalty (K_P) axis and a penalty_scale axis cannot be combined");
    return;
  }
  t->allow_only({"penalty_mode", "penalty", "penalty_scale", "damping", "restitution", "friction",
                 "rigid_impactor", "crease_angle"});
  GridContact& c = g.contact;
  parse_penalty(*t, g);
  if (const auto impactor = t->string("rigid_impactor")) {
    static constexpr std::array<std::string_view, 2> kImpactors = {"analytic", "meshed"};
    if (*impactor != "analytic" && *impactor != "meshed")
      t->fail("rigid_impactor", unknown_value_problem(*impactor, kImpactors));
    c.meshed_rigid_impactor = *impactor == "meshed";
    if (c.meshed_rigid_impactor &&
        (c.penalty_mode == PenaltyMode::element || g.other_axes.contains("penalty_scale")))
      t->fail("rigid_impactor",
              "the meshed rigid impactor takes the per-point K_P; the element-scaled penalty "
              "(penalty_mode, penalty_scale) applies to the analytic sphere only");
  }
  if (t->has("crease_angle")) {
    if (!c.meshed_rigid_impactor)
      t->fail("crease_angle",
              "applies only to the meshed rigid impactor (rigid_impactor = "
              "\"meshed\")");
    c.crease_angle = t->need_number("crease_angle");
    if (!kCreaseAngleRange.contains(c.crease_angle))
      t->fail("crease_angle", kCreaseAngleRange.problem(c.crease_angle));
  }
  c.damping = checked_as_axis(*t, "damping", "damping", c.damping);
  c.restitution = checked_as_axis(*t, "restitution", "restitution", c.restitution);
  c.friction = checked_as_axis(*t, "friction", "friction", c.friction);
}

ConvergencePoint parse_convergence_point(const StrictTable& t) {
  t.allow_only({"ER", "RLS", "KE"});
  ConvergencePoint p;
  p.modulus_ratio = positive(t, "ER");
  p.length_ratio = positive(t, "RLS");
  p.kinetic_energy = positive(t, "KE");
  return p;
}

void parse_convergence(const StrictTable& root, GridSpec& g) {
  const auto t = root.table("convergence");
  if (!t) return;
  t->allow_only({"points", "mesh_scales"});
  if (g.other_axes.contains("mesh_scale")) t->fail("", "cannot be combined with a mesh_scale axis");
  const std::vector<StrictTable> points = t->tables("points");
  if (points.empty()) t->fail("points", "needs at least one point {ER, RLS, KE}");
  for (const StrictTable& p : points) g.convergence.points.push_back(parse_convergence_point(p));
  const std::vector<double> scales = axis_values(*t, "mesh_scales", "mesh_scale");
  if (scales.size() < 2 || scales.size() > 3)
    t->fail("mesh_scales", fmt::format("needs 2 or 3 mesh scales (got {})", scales.size()));
  g.convergence.mesh_scales = scales;
}

// A non-empty array of distinct non-empty strings.
std::vector<std::string> name_array(const StrictTable& t, std::string_view key) {
  const toml::node* n = t.node(key);
  if (!n) t.fail(key, "required key is missing");
  const toml::array* a = n->as_array();
  if (!a || a->empty()) t.wrong_type(*n, t.key_path(key), "a non-empty array of body names");
  std::vector<std::string> names;
  for (const toml::node& item : *a) {
    const auto name = item.value<std::string>();
    if (!name || name->empty()) t.wrong_type(item, t.key_path(key), "a body name");
    if (std::find(names.begin(), names.end(), *name) != names.end())
      t.fail(key, fmt::format("names \"{}\" twice", *name));
    names.push_back(*name);
  }
  return names;
}

// The axes of a template: every key is a path into the scene, its value the array of values.
std::vector<TemplateAxis> template_axes(const StrictTable& t) {
  std::vector<TemplateAxis> axes;
  for (const auto& [key, line] : t.key_lines()) {
    const std::vector<double> values = t.number_array(key);
    for (size_t i = 0; i < values.size(); ++i) {
      const auto earlier_end = values.begin() + static_cast<long>(i);
      if (std::find(values.begin(), earlier_end, values[i]) != earlier_end)
        t.fail(key, fmt::format("[{}] repeats the value {}", i, values[i]));
    }
    axes.push_back({key, values, line});
  }
  std::sort(axes.begin(), axes.end(),
            [](const TemplateAxis& a, const TemplateAxis& b) { return a.line < b.line; });
  return axes;
}

// [template] with [axes] (and optional [levels]) of paths; the scene gives the rest, so the
// thesis grid's tables are refused beside it.
void parse_template(const StrictTable& root, GridSpec& g) {
  const StrictTable t = root.need_table("template");
  t.allow_only({"scene", "rigid"});
  for (std::string_view other : {"time", "artifact", "impactor", "contact", "convergence"})
    if (root.has(other))
      root.fail(other, "a grid over a scene takes this from its [template] scene; remove it");
  SceneTemplate s;
  s.scene = g.source.parent_path() / t.need_string("scene");
  s.rigid = name_array(t, "rigid");
  s.scene_line = t.line_of_key("scene");
  s.rigid_line = t.line_of_key("rigid");
  s.axes = template_axes(root.need_table("axes"));
  if (s.axes.empty()) root.fail("axes", "needs at least one path into the scene");
  if (const auto levels = root.table("levels")) s.levels = template_axes(*levels);
  g.scene_template = std::move(s);
}

}  // namespace

GridSpec parse_grid(std::string_view text, const std::filesystem::path& source) {
  const toml::table root = parse_toml(text, source);
  GridSpec g;
  g.source = source;
  const StrictTable t(root, "", source);
  t.allow_only({"title", "axes", "time", "artifact", "impactor", "contact", "convergence",
                "template", "levels"});
  g.title = t.string("title").value_or("");
  if (t.has("template")) {
    parse_template(t, g);
    return g;
  }
  if (t.has("levels")) t.fail("levels", "belongs to a grid over a scene ([template])");
  parse_axes(t, g);
  parse_time(t, g);
  parse_artifact(t, g);
  parse_impactor(t, g);
  parse_contact(t, g);
  parse_convergence(t, g);
  return g;
}

GridSpec parse_grid_file(const std::filesystem::path& file) {
  return parse_grid(read_config_text(file), file);
}

}  // namespace ccm::study
