// Material parameters, their validation and the derived Lamé constants.
#pragma once

#include <string>
#include <string_view>

namespace ccm {

enum class MaterialModel { neo_hookean, linear_elastic };

// The name table used by scene files and messages.
std::string_view to_string(MaterialModel model);
bool parse_material_model(std::string_view name, MaterialModel& out);

struct MaterialParams {
  MaterialModel model = MaterialModel::neo_hookean;
  double E = 0.0;    // Young's modulus [Pa]
  double nu = 0.0;   // Poisson's ratio [-]
  double rho = 0.0;  // reference density [kg/m^3]
};

// Empty when valid, else the first problem as "<field> ...": E > 0, -1 < nu < 0.5, rho > 0, all
// finite.
std::string validate(const MaterialParams& m);

struct Lame {
  double lambda;
  double mu;
};

// lambda = E nu / ((1+nu)(1-2nu)), mu = E / (2(1+nu))   (docs/equations.md "Material")
inline Lame lame_from(const MaterialParams& m) {
  return {m.E * m.nu / ((1.0 + m.nu) * (1.0 - 2.0 * m.nu)), m.E / (2.0 * (1.0 + m.nu))};
}

// Dilatational wave speed c_d = sqrt((lambda + 2 mu) / rho)   (docs/equations.md "Material")
double dilatational_wave_speed(const MaterialParams& m);

}  // namespace ccm
