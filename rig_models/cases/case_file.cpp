#include "rig_models/cases/case_file.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>

#include "config/strict_table.hpp"
#include "rig_models/cases/case_code.hpp"
#include "rig_models/cases/sourced_value.hpp"
#include "rig_models/core/rig_error.hpp"

namespace ccm::rig {
namespace {

namespace fs = std::filesystem;

constexpr int kCaseCount = 12;

// Every key of [rig]: its member, unit and bound; read alike from cases.toml (all required) and
// from a trial folder's rig file (any of them, trial_rig_file.hpp).
struct RigKey {
  std::string_view key, unit;
  SourcedValue RigParameters::*member;
  ValueBound bound;
};

constexpr ValueBound kPositive{};
constexpr ValueBound kNonNegative{0.0, false};
constexpr std::array<RigKey, 20> kRigKeys = {{
    {"hanging_mass", "kg", &RigParameters::hanging_mass, kPositive},
    {"impactor_mass", "kg", &RigParameters::impactor_mass, kPositive},
    {"spring_stiffness", "N/m", &RigParameters::spring_stiffness, kPositive},
    {"spring_length", "m", &RigParameters::spring_length, kPositive},
    {"spring_cylinder_diameter", "m", &RigParameters::spring_cylinder_diameter, kPositive},
    {"artifact_mass", "kg", &RigParameters::artifact_mass, kPositive},
    {"artifact_inertia_pivot", "kg m^2", &RigParameters::artifact_inertia_pivot, kPositive},
    {"clamp_stiffness", "N m/rad", &RigParameters::clamp_stiffness, kPositive},
    {"clamp_damping", "N m s/rad", &RigParameters::clamp_damping, kNonNegative},
    {"mat_stiffness", "N/m^n", &RigParameters::mat_stiffness, kNonNegative},
    {"mat_exponent", "1", &RigParameters::mat_exponent, kPositive},
    {"mat_damping", "s/m", &RigParameters::mat_damping, kNonNegative},
    {"pivot_to_sensor", "m", &RigParameters::pivot_to_sensor, kPositive},
    {"sensor_area", "m^2", &RigParameters::sensor_area, kPositive},
    {"sensor_deadband", "kPa", &RigParameters::sensor_deadband, kPositive},
    {"pressure_rate", "Hz", &RigParameters::pressure_rate, kPositive},
    {"angle_rate", "Hz", &RigParameters::angle_rate, kPositive},
    {"velocity_rate", "Hz", &RigParameters::velocity_rate, kPositive},
    {"low_pass_cutoff", "Hz", &RigParameters::low_pass_cutoff, kPositive},
    {"trials_per_case", "count", &RigParameters::trials_per_case, kPositive},
}};

std::vector<std::string_view> rig_key_names() {
  std::vector<std::string_view> names;
  for (const RigKey& k : kRigKeys) names.push_back(k.key);
  return names;
}

void check_low_pass(const StrictTable& t, const RigParameters& r) {
  if (2.0 * r.low_pass_cutoff.value > r.pressure_rate.value)
    t.fail("low_pass_cutoff", fmt::format("{} Hz is above the Nyquist frequency of the {} Hz "
                                          "pressure sensor",
                                          r.low_pass_cutoff.value, r.pressure_rate.value));
}

RigParameters read_rig(const StrictTable& root) {
  const StrictTable t = root.need_table("rig");
  t.allow_only(rig_key_names());
  RigParameters r;
  for (const RigKey& k : kRigKeys) r.*k.member = read_sourced(t, k.key, k.unit, k.bound);
  check_low_pass(t, r);
  return r;
}

DriveParameters read_drive(const StrictTable& root) {
  const StrictTable t = root.need_table("drive");
  t.allow_only({"velocity_smoothing", "track_static_friction", "track_friction", "track_damping",
                "string_stiffness", "string_damping"});
  DriveParameters d;
  d.velocity_smoothing = read_sourced(t, "velocity_smoothing", "s");
  d.track_static_friction = read_sourced(t, "track_static_friction", "1", {0.0, false});
  d.track_friction = read_sourced(t, "track_friction", "1", {0.0, false});
  if (d.track_friction.value > d.track_static_friction.value)
    t.fail("track_friction", fmt::format("the kinetic coefficient {} exceeds the static one {}",
                                         d.track_friction.value, d.track_static_friction.value));
  d.track_damping = read_sourced(t, "track_damping", "N s/m", {0.0, false});
  d.string_stiffness = read_sourced(t, "string_stiffness", "N/m");
  d.string_damping = read_sourced(t, "string_damping", "N s/m", {0.0, false});
  return d;
}

SimulationParameters read_simulation(const StrictTable& root) {
  const StrictTable t = root.need_table("simulation");
  t.allow_only({"lead", "output_interval", "after_contact"});
  SimulationParameters p;
  p.lead = read_sourced(t, "lead", "s", {0.0, false});
  p.output_interval = read_sourced(t, "output_interval", "s");
  p.after_contact = read_sourced(t, "after_contact", "s");
  return p;
}

template <typename Kind>
Kind read_kind(const StrictTable& t, std::string_view key, std::array<Kind, 2> kinds) {
  const std::string name = t.need_string(key);
  for (Kind k : kinds)
    if (name == name_of(k)) return k;
  t.fail(key,
         fmt::format("'{}' is not one of: {}, {}", name, name_of(kinds[0]), name_of(kinds[1])));
}

PivotFriction read_friction(const StrictTable& c) {
  const StrictTable t = c.need_table("pivot_friction");
  t.allow_only({"mu_s", "mu_k", "source"});
  PivotFriction f{t.need_number("mu_s"), t.need_number("mu_k"), t.need_string("source")};
  if (f.mu_s < 0.0) t.fail("mu_s", fmt::format("must be >= 0 (got {})", f.mu_s));
  if (f.mu_k < 0.0) t.fail("mu_k", fmt::format("must be >= 0 (got {})", f.mu_k));
  return f;
}

// The code must be Table 3.2's for the number and say the same as the other fields.
void check_code(const StrictTable& t, const RigCase& c) {
  if (!is_case_code(c.code))
    t.fail("code",
           fmt::format("'{}' is not a case code of thesis Table 3.2 (RX025 ... FF100)", c.code));
  const std::string expected = table_3_2_code(c.number);
  if (c.code != expected)
    t.fail("code",
           fmt::format("case {} of Table 3.2 is '{}', not '{}'", c.number, expected, c.code));
  if ((c.code[0] == 'R') != (c.impactor == ImpactorKind::rigid))
    t.fail("impactor",
           fmt::format("'{}' disagrees with the code '{}'", name_of(c.impactor), c.code));
  if ((c.code[1] == 'X') != (c.artifact == ArtifactKind::fixed))
    t.fail("artifact",
           fmt::format("'{}' disagrees with the code '{}'", name_of(c.artifact), c.code));
  const int cm_per_s = std::stoi(c.code.substr(2));
  if (std::abs(c.target_speed.value * 100.0 - cm_per_s) > 1e-9)
    t.fail("target_speed",
           fmt::format("{} m/s disagrees with the code '{}'", c.target_speed.value, c.code));
}

RigCase read_case(const StrictTable& t) {
  t.allow_only(
      {"number", "code", "target_speed", "impactor", "artifact", "pivot_friction", "source"});
  RigCase c;
  const long number = t.need_integer("number");
  if (number < 1 || number > kCaseCount)
    t.fail("number", fmt::format("must be 1 ... {} (got {})", kCaseCount, number));
  c.number = static_cast<int>(number);
  c.code = t.need_string("code");
  c.target_speed = read_sourced(t, "target_speed", "m/s");
  c.impactor = read_kind(t, "impactor", std::array{ImpactorKind::rigid, ImpactorKind::flexible});
  c.artifact = read_kind(t, "artifact", std::array{ArtifactKind::fixed, ArtifactKind::free});
  c.source = t.need_string("source");
  check_code(t, c);
  if (c.artifact == ArtifactKind::free)
    c.pivot_friction = read_friction(t);
  else if (t.has("pivot_friction"))
    t.fail("pivot_friction",
           "a fixed artifact is held by the pin's clamp ([rig] clamp_stiffness, "
           "clamp_damping); pivot friction is for free artifacts");
  return c;
}

std::vector<RigCase> read_cases(const StrictTable& root) {
  std::vector<RigCase> cases;
  std::array<bool, kCaseCount + 1> seen{};
  for (const StrictTable& t : root.need_tables("cases")) {
    cases.push_back(read_case(t));
    const int n = cases.back().number;
    if (seen[static_cast<size_t>(n)]) t.fail("number", fmt::format("case {} is given twice", n));
    seen[static_cast<size_t>(n)] = true;
  }
  for (int n = 1; n <= kCaseCount; ++n)
    if (!seen[static_cast<size_t>(n)])
      root.fail("cases", fmt::format("case {} ({}) of Table 3.2 is missing", n, table_3_2_code(n)));
  std::sort(cases.begin(), cases.end(),
            [](const RigCase& a, const RigCase& b) { return a.number < b.number; });
  return cases;
}

}  // namespace

std::string table_3_2_code(int number) {
  // Table 3.2: cases 1-3 rigid/fixed, 4-6 flexible/fixed, 7-9 rigid/free, 10-12 flexible/free,
  // each at 0.25, 0.50, 1.00 m/s.
  static constexpr std::array<const char*, 4> kConfig = {"RX", "FX", "RF", "FF"};
  static constexpr std::array<const char*, 3> kSpeed = {"025", "050", "100"};
  if (number < 1 || number > kCaseCount)
    throw std::out_of_range(fmt::format("Table 3.2 has no case {}", number));
  const auto i = static_cast<size_t>(number - 1);
  return std::string(kConfig[i / 3]) + kSpeed[i % 3];
}

RigCaseTable parse_case_table(std::string_view text, const fs::path& source) {
  toml::table root;
  try {
    root = toml::parse(text, source.string());
  } catch (const toml::parse_error& e) {
    throw rig_input_error(source, static_cast<int>(e.source().begin.line), "", e.description());
  }
  const StrictTable fields(root, "", source);
  fields.allow_only({"rig", "drive", "simulation", "cases"});
  RigCaseTable table;
  table.source = source;
  table.rig = read_rig(fields);
  table.drive = read_drive(fields);
  table.simulation = read_simulation(fields);
  table.cases = read_cases(fields);
  return table;
}

void override_rig(const StrictTable& t, RigParameters& rig) {
  t.allow_only(rig_key_names());
  for (const RigKey& k : kRigKeys)
    if (t.has(k.key)) rig.*k.member = read_sourced(t, k.key, k.unit, k.bound);
  check_low_pass(t, rig);
}

RigCaseTable read_case_table(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw rig_input_error(file, 0, "", "cannot open the file for reading");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_case_table(text.str(), file);
}

}  // namespace ccm::rig
