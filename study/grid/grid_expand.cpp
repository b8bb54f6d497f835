#include "study/grid/grid_expand.hpp"

#include <string>

namespace ccm::study {
namespace {

using OtherAxes = std::map<std::string, std::vector<double>>;

// Appends one point per combination of the other axes (name order, the last one fastest).
void expand_other_axes(const OtherAxes& axes, OtherAxes::const_iterator axis, GridPoint point,
                       std::vector<GridPoint>& out) {
  if (axis == axes.end()) {
    point.index = static_cast<int>(out.size());
    out.push_back(point);
    return;
  }
  for (const double v : axis->second) {
    point.other_axes[axis->first] = v;
    expand_other_axes(axes, std::next(axis), point, out);
  }
}

// A template's axes as named in other_axes ("axes.<path>" sort before "levels.<path>").
OtherAxes template_other_axes(const SceneTemplate& t) {
  OtherAxes axes;
  for (const TemplateAxis& a : t.axes) axes[std::string(kTemplateAxisPrefix) + a.path] = a.values;
  for (const TemplateAxis& a : t.levels)
    axes[std::string(kTemplateLevelPrefix) + a.path] = a.values;
  return axes;
}

}  // namespace

long grid_size(const GridSpec& spec) {
  if (spec.scene_template) {
    long n = 1;
    for (const auto& [name, values] : template_other_axes(*spec.scene_template))
      n *= static_cast<long>(values.size());
    return n;
  }
  long n = static_cast<long>(spec.modulus_ratios.size() * spec.length_ratios.size() *
                             spec.kinetic_energies.size());
  for (const auto& [name, values] : spec.other_axes) n *= static_cast<long>(values.size());
  return n;
}

std::vector<GridPoint> expand_grid(const GridSpec& spec) {
  std::vector<GridPoint> out;
  out.reserve(static_cast<size_t>(grid_size(spec)));
  if (spec.scene_template) {
    const OtherAxes axes = template_other_axes(*spec.scene_template);
    expand_other_axes(axes, axes.begin(), GridPoint{}, out);
    return out;
  }
  for (const double er : spec.modulus_ratios)
    for (const double rls : spec.length_ratios)
      for (const double ke : spec.kinetic_energies) {
        GridPoint p;
        p.modulus_ratio = er;
        p.length_ratio = rls;
        p.kinetic_energy = ke;
        expand_other_axes(spec.other_axes, spec.other_axes.begin(), p, out);
      }
  return out;
}

std::vector<GridPoint> expand_convergence(const GridSpec& spec) {
  std::vector<GridPoint> out;
  int index = static_cast<int>(grid_size(spec));
  for (const ConvergencePoint& c : spec.convergence.points)
    for (const double scale : spec.convergence.mesh_scales) {
      GridPoint p;
      p.index = index++;
      p.modulus_ratio = c.modulus_ratio;
      p.length_ratio = c.length_ratio;
      p.kinetic_energy = c.kinetic_energy;
      p.other_axes["mesh_scale"] = scale;
      out.push_back(p);
    }
  return out;
}

}  // namespace ccm::study
