// One point of a trade-study grid (thesis 2.8, Table 2.2) and the two models run at each point.
// Shared vocabulary of the grid reader, the point runner, the metrics and the store.
#pragma once

#include <map>
#include <string>
#include <string_view>

namespace ccm::study {

// The two simulations of a grid point: "ccm" = meshed impactor sphere with DCR contact;
// "rigid" = analytic rigid sphere with penalty contact (thesis 2.8).
enum class ImpactModel { ccm, rigid };

constexpr std::string_view to_string(ImpactModel m) {
  return m == ImpactModel::ccm ? "ccm" : "rigid";
}

struct GridPoint {
  int index = 0;                             // position in the grid's row-major order, from 0
  double modulus_ratio = 1.0;                // ER = E_I / E_A            (eq. 2.32)
  double length_ratio = 1.0;                 // RLS = D_I / L_A           (eq. 2.33)
  double kinetic_energy = 0.0;               // KE_I, impactor kinetic energy [J]
  std::map<std::string, double> other_axes;  // further swept parameters by name (e.g. "nu")
};

}  // namespace ccm::study
