#include "engine/material/material.hpp"

#include <fmt/format.h>

#include <cmath>

#include "engine/core/parameter_ranges.hpp"

namespace ccm {

std::string_view to_string(MaterialModel model) {
  switch (model) {
    case MaterialModel::neo_hookean:
      return "neo_hookean";
    case MaterialModel::linear_elastic:
      return "linear_elastic";
  }
  return "unknown";
}

bool parse_material_model(std::string_view name, MaterialModel& out) {
  for (auto m : {MaterialModel::neo_hookean, MaterialModel::linear_elastic}) {
    if (name == to_string(m)) {
      out = m;
      return true;
    }
  }
  return false;
}

std::string validate(const MaterialParams& m) {
  if (!std::isfinite(m.E) || m.E <= 0.0) return fmt::format("E must be > 0 (got {})", m.E);
  if (!kPoissonRange.contains(m.nu)) return "nu " + kPoissonRange.problem(m.nu);
  if (!std::isfinite(m.rho) || m.rho <= 0.0) return fmt::format("rho must be > 0 (got {})", m.rho);
  return {};
}

double dilatational_wave_speed(const MaterialParams& m) {
  const Lame l = lame_from(m);
  return std::sqrt((l.lambda + 2.0 * l.mu) / m.rho);
}

}  // namespace ccm
