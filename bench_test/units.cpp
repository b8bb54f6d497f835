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

struct Unit {
  std::string_view name;
  double factor;        // to SI
  std::string_view si;  // the SI unit it converts to
};

// One table, SI first in each quantity.
constexpr auto kUnits = std::to_array<Unit>({
    {"1", 1.0, "1"},
    {"s", 1.0, "s"},
    {"ms", 1e-3, "s"},
    {"us", 1e-6, "s"},
    {"m", 1.0, "m"},
    {"cm", 1e-2, "m"},
    {"mm", 1e-3, "m"},
    {"um", 1e-6, "m"},
    {"in", kInch, "m"},
    {"m/s", 1.0, "m/s"},
    {"mm/s", 1e-3, "m/s"},
    {"mm/ms", 1.0, "m/s"},
    {"km/h", 1.0 / 3.6, "m/s"},
    {"in/s", kInch, "m/s"},
    {"m/s^2", 1.0, "m/s^2"},
    {"m/s2", 1.0, "m/s^2"},
    {"mm/s^2", 1e-3, "m/s^2"},
    {"g", kStandardGravity, "m/s^2"},
    {"N", 1.0, "N"},
    {"kN", 1e3, "N"},
    {"mN", 1e-3, "N"},
    {"lbf", kPoundForce, "N"},
    {"N*m", 1.0, "N m"},
    {"Nm", 1.0, "N m"},
    {"N*mm", 1e-3, "N m"},
    {"Nmm", 1e-3, "N m"},
    {"Pa", 1.0, "Pa"},
    {"kPa", 1e3, "Pa"},
    {"MPa", 1e6, "Pa"},
    {"bar", 1e5, "Pa"},
    {"psi", kPsi, "Pa"},
    {"mmHg", 133.322387415, "Pa"},
    {"J", 1.0, "J"},
    {"mJ", 1e-3, "J"},
    {"kJ", 1e3, "J"},
    {"rad", 1.0, "rad"},
    {"deg", std::numbers::pi / 180.0, "rad"},
    {"rad/s", 1.0, "rad/s"},
    {"deg/s", std::numbers::pi / 180.0, "rad/s"},
    {"V", 1.0, "V"},
});

}  // namespace

std::optional<double> si_factor(std::string_view unit) {
  for (const Unit& u : kUnits)
    if (u.name == unit) return u.factor;
  return std::nullopt;
}

std::string_view si_unit(std::string_view unit) {
  for (const Unit& u : kUnits)
    if (u.name == unit) return u.si;
  return {};
}

std::vector<std::string_view> known_units() {
  std::vector<std::string_view> out;
  for (const Unit& u : kUnits) out.push_back(u.name);
  return out;
}

}  // namespace ccm::bench
