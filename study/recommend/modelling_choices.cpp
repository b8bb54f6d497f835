#include "study/recommend/modelling_choices.hpp"

#include <fmt/format.h>

#include <set>

namespace ccm::study {

std::string ModellingChoice::text() const {
  const std::string u = unit.empty() ? "" : " " + unit;
  if (value)
    return fmt::format("{}: {:g}{}{}", label, *value, u,
                       axis.empty() ? "" : fmt::format(" (grid axis {})", axis));
  std::string list;
  for (double v : levels) list += fmt::format("{}{:g}", list.empty() ? "" : ", ", v);
  return fmt::format("{}: per level of grid axis {}: {}{}", label, axis, list, u);
}

namespace {

struct ChoiceSpec {
  const char* key;
  const char* label;
  const char* unit;
  const char* axis;  // the other_axes name that overrides it
  double fixed;
};

ModellingChoice choice(const ChoiceSpec& c, const GridSpec& spec, const AxisLevels& used) {
  ModellingChoice out{c.key, c.label, c.unit, "", c.fixed, {}};
  const auto axis = spec.other_axes.find(c.axis);
  if (axis == spec.other_axes.end()) return out;
  out.axis = c.axis;
  if (const auto level = used.find(c.axis); level != used.end()) {
    out.value = level->second;
  } else if (axis->second.size() == 1) {
    out.value = axis->second.front();
  } else {
    out.value.reset();
    out.levels = axis->second;
  }
  return out;
}

// A grid over a scene: its choices are the scene's (as written in the template), and the ones
// it sweeps are its axes and levels, each given per level or at the level an answer used.
std::vector<ModellingChoice> template_choices(const SceneTemplate& t, const AxisLevels& used) {
  std::vector<ModellingChoice> out;
  const auto add = [&](const TemplateAxis& a, std::string_view prefix) {
    const std::string axis = std::string(prefix) + a.path;
    ModellingChoice c{a.path, a.path, "", axis, std::nullopt, {}};
    if (const auto level = used.find(axis); level != used.end())
      c.value = level->second;
    else if (a.values.size() == 1)
      c.value = a.values.front();
    else
      c.levels = a.values;
    out.push_back(c);
  };
  for (const TemplateAxis& a : t.axes) add(a, kTemplateAxisPrefix);
  for (const TemplateAxis& a : t.levels) add(a, kTemplateLevelPrefix);
  return out;
}

}  // namespace

std::vector<ModellingChoice> modelling_choices(const GridSpec& spec, const AxisLevels& used) {
  if (spec.scene_template) return template_choices(*spec.scene_template, used);
  const ChoiceSpec specs[] = {
      {"rigid_penalty", "rigid penalty K_P per quadrature point", "N/m", "penalty",
       spec.contact.penalty},
      {"rigid_damping", "rigid damping zeta (fraction of critical)", "", "damping",
       spec.contact.damping},
      {"dcr_restitution", "DCR pair restitution e", "", "restitution", spec.contact.restitution},
      {"dcr_friction", "DCR pair friction mu", "", "friction", spec.contact.friction},
      {"artifact_mesh_size", "artifact mesh size", "m", "artifact_mesh_size",
       spec.artifact.mesh_size},
      {"artifact_contact_mesh_size", "artifact contact mesh size (0: none)", "m", "",
       spec.artifact.contact_mesh_size},
      {"artifact_contact_radius", "artifact contact refinement radius", "m", "",
       spec.artifact.contact_radius},
      {"impactor_mesh_size_ratio", "impactor mesh size / D_I", "", "impactor_mesh_ratio",
       spec.impactor.mesh_size_ratio},
      {"impactor_contact_mesh_size", "impactor contact mesh size (0: none)", "m", "",
       spec.impactor.contact_mesh_size},
      {"impactor_contact_radius", "impactor contact refinement radius", "m", "",
       spec.impactor.contact_radius},
  };
  std::vector<ModellingChoice> out;
  std::set<std::string> covered = {"mesh_scale"};
  for (const ChoiceSpec& c : specs) {
    out.push_back(choice(c, spec, used));
    if (*c.axis) covered.insert(c.axis);
  }
  for (const auto& [name, values] : spec.other_axes)
    if (!covered.contains(name))
      out.push_back(choice({name.c_str(), name.c_str(), "", name.c_str(), 0.0}, spec, used));
  return out;
}

}  // namespace ccm::study
