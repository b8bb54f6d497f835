#include "bench_test/units.hpp"

#include <array>
#include <numbers>
#include <utility>

namespace ccm::bench {

namespace {

constexpr double kStandardGravity = 9.80665;     // m/s^2, the g of accelerometers (CGPM 1901)
constexpr double kInch = 0.0254;                 // m
constexpr double kPoundForce = 4.4482216152605;  // N
constexpr double kPsi = 6894.757293168;          // Pa

// One table, SI first in each quantity.
constexpr auto kUnits = std::to_array<std::pair<std::string_view, double>>({
    {"1", 1.0},  // dimensionless
    {"s", 1.0},
    {"ms", 1e-3},
    {"us", 1e-6},  // time
    {"m", 1.0},
    {"cm", 1e-2},
    {"mm", 1e-3},  // length
    {"um", 1e-6},
    {"in", kInch},
    {"m/s", 1.0},
    {"mm/s", 1e-3},
    {"mm/ms", 1.0},  // velocity
    {"km/h", 1.0 / 3.6},
    {"in/s", kInch},
    {"m/s^2", 1.0},
    {"m/s2", 1.0},
    {"mm/s^2", 1e-3},  // acceleration
    {"g", kStandardGravity},
    {"N", 1.0},
    {"kN", 1e3},
    {"mN", 1e-3},  // force
    {"lbf", kPoundForce},
    {"N*m", 1.0},
    {"Nm", 1.0},
    {"N*mm", 1e-3},  // moment
    {"Nmm", 1e-3},
    {"Pa", 1.0},
    {"kPa", 1e3},
    {"MPa", 1e6},  // pressure
    {"bar", 1e5},
    {"psi", kPsi},
    {"mmHg", 133.322387415},
    {"J", 1.0},
    {"mJ", 1e-3},
    {"kJ", 1e3},  // energy
    {"rad", 1.0},
    {"deg", std::numbers::pi / 180.0},  // angle
    {"rad/s", 1.0},
    {"deg/s", std::numbers::pi / 180.0},  // angular velocity
    {"V", 1.0},                           // a raw voltage
});

}  // namespace

std::optional<double> si_factor(std::string_view unit) {
  for (const auto& [name, factor] : kUnits)
    if (name == unit) return factor;
  return std::nullopt;
}

std::vector<std::string_view> known_units() {
  std::vector<std::string_view> out;
  for (const auto& u : kUnits) out.push_back(u.first);
  return out;
}

}  // namespace ccm::bench
