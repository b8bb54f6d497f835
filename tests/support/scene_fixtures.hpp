// Small scene-file texts the scene and contact tests share. Line numbers matter to the tests
// that check error messages: the one-cube scene has 12 lines.
#pragma once

#include <string>

#include "run/scene/scene_file.hpp"
#include "run/scene/scene_run.hpp"

namespace ccm::test {

inline const std::string kTimeToml = "[time]\nend = 1e-3\n";

// A soft 1 cm cube body named `name` (10 lines).
inline std::string cube_body_toml(const std::string& name) {
  return "[[bodies]]\nname = \"" + name +
         "\"\n[bodies.material]\nE = 1e5\nnu = 0.3\nrho = 1000.0\n[bodies.geometry]\n"
         "shape = \"box\"\nsize = [0.01, 0.01, 0.01]\nmesh_size = 0.005\n";
}

// A soft 1 cm cube "base" struck at 1 m/s by a stiffer box "striker" (DCR contact), 2 ms: the
// scene of `ccm compare` and of the grids over a scene in the tests.
inline const char* const kStrikeScene = R"([time]
end = 2e-3
output_interval = 1e-4

[[bodies]]
name = "base"
[bodies.material]
E = 1e5
nu = 0.3
rho = 1000.0
[bodies.geometry]
shape = "box"
size = [0.01, 0.01, 0.01]
mesh_size = 0.005

[[bodies]]
name = "striker"
initial_velocity = [0.0, 0.0, -1.0]
[bodies.material]
E = 1e7
nu = 0.3
rho = 1000.0
[bodies.geometry]
shape = "box"
size = [0.006, 0.006, 0.004]
mesh_size = 0.003
[bodies.placement]
translate = [0.002, 0.002, 0.0101]

[contact]
model = "dcr"
surfaces = ["base", "striker"]
)";

// One cube named "cube"; lines 1-12.
inline const std::string kOneCubeScene = kTimeToml + cube_body_toml("cube");

// The message of the ConfigError parsing `text` (as "s.toml") throws, or "(no error)".
inline std::string scene_error_of(const std::string& text) {
  try {
    parse_scene(text, "s.toml");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "(no error)";
}

// The message of the ConfigError that parsing and assembling `text` (as "s.toml": model,
// contact, joints) throws, or "(no error)".
inline std::string assembly_error_of(const std::string& text) {
  try {
    assemble_scene_run(parse_scene(text, "s.toml"));
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace ccm::test
