#include "rig_models/cases/rig_case.hpp"

#include <fmt/format.h>

#include <numbers>
#include <stdexcept>

namespace ccm::rig {

double spring_cylinder_area(const RigParameters& rig) {
  const double d = rig.spring_cylinder_diameter.value;
  return std::numbers::pi * d * d / 4.0;
}

double spring_modulus(const RigParameters& rig) {
  return rig.spring_stiffness.value * rig.spring_length.value / spring_cylinder_area(rig);  // (3.1)
}

std::string_view name_of(ImpactorKind kind) {
  return kind == ImpactorKind::rigid ? "rigid" : "flexible";
}

std::string_view name_of(ArtifactKind kind) {
  return kind == ArtifactKind::fixed ? "fixed" : "free";
}

const RigCase& RigCaseTable::find(std::string_view code) const {
  for (const RigCase& c : cases)
    if (c.code == code) return c;
  throw std::out_of_range(fmt::format("no rig case '{}' in {}", code, source.string()));
}

}  // namespace ccm::rig
