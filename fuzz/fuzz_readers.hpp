// One function per fuzz target: an input handed to one reader of outside input, which may refuse it
// only with its own error type (fuzz_input.hpp). The fuzz targets (ccm_fuzz.cpp) call these; the
// unit tests replay the inputs that once failed (tests/data/fuzz/<target>/) through the same
// functions.
#pragma once

#include <array>
#include <cstdlib>

#include "bench_test/bench_mapping.hpp"
#include "bench_test/bench_trials.hpp"
#include "config/config_error.hpp"
#include "db/sqlite/connection.hpp"  // StoreError
#include "db/store/study_store.hpp"
#include "engine/mesh/gmsh_mesher.hpp"  // MeshError
#include "engine/mesh/readers/mesh_file.hpp"
#include "fuzz/fuzz_input.hpp"
#include "rig_models/measurement/trial_csv.hpp"
#include "run/scene/scene_file.hpp"
#include "study/grid/grid_file.hpp"

namespace ccm::fuzz {

// A scene file (TOML, docs/scene-file.md) through the strict reader and every check behind it.
inline void scene_file_input(std::string_view text) {
  expect_only<ConfigError>([&] { parse_scene(text, scratch_dir() / "scene.toml"); });
}

// A trade-study grid file (TOML, docs/grid-file.md) through the strict reader and its checks.
inline void grid_file_input(std::string_view text) {
  expect_only<ConfigError>([&] { study::parse_grid(text, scratch_dir() / "grid.toml"); });
}

// A mesh file through read_mesh_file, chosen by `extension` (".unv", ".inp", ".msh";
// docs/meshes.md): refused only with a MeshError.
inline void mesh_file_input(std::string_view text, const std::string& extension) {
  const auto file = write_input("mesh" + extension, text);
  expect_only<MeshError>([&] { read_mesh_file_with_report(file); });
}

// The bench-test mapping the trial CSV target reads under: most of what a mapping can ask (units,
// a sparse file, comment lines, a units row under the header), docs/bench-test.md.
inline const bench::BenchMapping& fuzz_bench_mapping() {
  static const bench::BenchMapping m = bench::parse_bench_mapping(R"(
[trials]
files = "t*.csv"
time_column = "time"
time_unit = "ms"
comment = "#"
skip_after_header = 1
sparse = true

[[channels]]
name = "accel"
column = "a"
unit = "g"
observable = "impactor.a"
axis = "z"

[[channels]]
name = "force"
column = "F"
unit = "kN"
observable = "contact.force"
axis = "z"
)",
                                                                  "bench.toml");
  return m;
}

// A measured trial CSV through both readers: the rig's and a bench test's.
inline void trial_csv_input(std::string_view text) {
  expect_only<ConfigError>([&] { rig::parse_trial_csv(text, scratch_dir() / "RX025_t1.csv"); });
  expect_only<ConfigError>(
      [&] { bench::parse_bench_trial(text, scratch_dir() / "t1.csv", fuzz_bench_mapping()); });
}

// A store file opened as the reading commands open it (read only: status, recommend, report) and
// read through: the study, its points, metrics, fits and grid. Refused only with a StoreError.
inline void store_file_input(std::string_view bytes) {
  const auto file = write_input("store.sqlite", bytes);
  std::error_code ec;
  std::filesystem::remove(file.string() + "-wal", ec);
  std::filesystem::remove(file.string() + "-shm", ec);
  expect_only<db::StoreError>([&] {
    db::StudyStore store(file, db::Access::read_only);
    if (!store.open_existing_study()) return;
    store.status();
    store.load_metrics();
    store.load_fits();
    store.load_grid();
  });
}

// The fuzz targets by name, each with its entry point above: the names ccm_fuzz runs as
// (fuzz/CMakeLists.txt) and the folders of tests/data/fuzz/.
struct Target {
  std::string_view name;
  void (*read)(std::string_view input);
};

inline const std::array<Target, 7>& targets() {
  static const std::array<Target, 7> all = {{
      {"fuzz_scene_file", scene_file_input},
      {"fuzz_grid_file", grid_file_input},
      {"fuzz_unv_mesh", [](std::string_view s) { mesh_file_input(s, ".unv"); }},
      {"fuzz_inp_mesh", [](std::string_view s) { mesh_file_input(s, ".inp"); }},
      {"fuzz_msh_mesh", [](std::string_view s) { mesh_file_input(s, ".msh"); }},
      {"fuzz_trial_csv", trial_csv_input},
      {"fuzz_store_file", store_file_input},
  }};
  return all;
}

// The target called `name`; nullptr for none.
inline const Target* target_named(std::string_view name) {
  for (const Target& t : targets())
    if (t.name == name) return &t;
  return nullptr;
}

}  // namespace ccm::fuzz
