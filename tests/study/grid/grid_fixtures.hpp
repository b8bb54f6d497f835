// A small valid grid file for the grid and runner tests, and a helper to get a parse error.
#pragma once

#include <string>
#include <string_view>

#include "run/scene/scene.hpp"
#include "study/grid/grid_file.hpp"

namespace ccm::test {

// Line numbers matter: the error tests name them (line 1 is "[axes]").
inline constexpr std::string_view kSmallGrid = R"([axes]
ER = [1.0, 100.0]
RLS = [0.5, 1.0, 1.5]
KE = [10.0, 100.0]

[time]
contact_time = 0.1
end = 0.15
output_interval = 1e-3

[artifact]
length = 1.0
thickness = 0.25
E = 1000.0
nu = 0.49
rho = 1000.0
mesh_size = 0.1

[impactor]
nu = 0.49
rho = 1000.0
mesh_size_ratio = 0.2
)";

// The plate, sphere and contact sections of the tiny grids the study tests run for real (coarse
// meshes: each run well under a second); a test appends its own [axes] and [time] before them.
inline constexpr std::string_view kTinyGridBodies = R"([artifact]
length = 1.0
thickness = 0.25
E = 1000.0
nu = 0.3
rho = 1000.0
mesh_size = 0.25
support = "base"
[impactor]
nu = 0.3
rho = 1000.0
mesh_size_ratio = 0.5
[contact]
penalty = 1.0e6
)";

// Two points x two models of kTinyGridBodies, each run well under a second: coarse meshes, 30 ms
// of simulated time, first touch at 20 ms.
inline std::string tiny_study_grid() {
  return R"(title = "tiny"
[axes]
ER = [1.0, 100.0]
RLS = [0.5]
KE = [0.001]
[time]
contact_time = 0.02
end = 0.03
output_interval = 1e-3
)" + std::string(kTinyGridBodies);
}

// kTinyGridBodies' bodies on a stiffer plate (E_A 1e5 Pa), hit harder, as whole impacts: each
// run ends 5 ms after its bodies separate, the guard `end` (0.4 s) far beyond the impact. The
// rigid run separates near 0.05 s; at ER 1 the CCM run near 0.24 s. `extra_axes` (lines such as
// "density_ratio = [1.0, 7.8]\n") join ER 1 and 100, RLS 0.5, KE 1 J.
inline std::string whole_impact_grid(std::string_view title, std::string_view extra_axes = "") {
  std::string bodies(kTinyGridBodies);
  bodies.replace(bodies.find("E = 1000.0"), 10, "E = 1.0e5");
  return "title = \"" + std::string(title) +
         "\"\n[axes]\nER = [1.0, 100.0]\nRLS = [0.5]\nKE = [1.0]\n" + std::string(extra_axes) +
         "[time]\ncontact_time = 0.02\nend = 0.4\noutput_interval = 1e-3\n"
         "end_after_separation = 0.005\n" +
         bodies;
}
inline constexpr double kWholeImpactGuard = 0.4;  // s, whole_impact_grid's end

// kSmallGrid with `tail` (further tables) appended after its last line.
inline std::string small_grid_plus(std::string_view tail) {
  std::string text(kSmallGrid);
  text.append(tail);
  return text;
}

// The message of the ConfigError that parsing `text` as "g.toml" throws ("" when it parses).
inline std::string grid_error_of(std::string_view text) {
  try {
    (void)study::parse_grid(text, "g.toml");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

// kSmallGrid with the first occurrence of `from` replaced by `to`.
inline std::string small_grid_with(std::string_view from, std::string_view to) {
  std::string s(kSmallGrid);
  const size_t at = s.find(from);
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}

}  // namespace ccm::test
