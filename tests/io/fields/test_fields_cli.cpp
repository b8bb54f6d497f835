// Fields from the command line (docs/fields.md): `ccm run` with `[output] fields`, `ccm run -
// --fields` fed by `ccm study scene`, and `ccm rig run --fields`; bad input refused with exit 2
// and nothing written.
#include <fmt/format.h>
#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/fields/field_recorder.hpp"
#include "io/fields/xdmf_text.hpp"
#include "tests/io/fields/field_files_check.hpp"
#include "tests/study/grid/grid_fixtures.hpp"
#include "tests/support/scene_fixtures.hpp"
#include "tests/support/temp_dir.hpp"

namespace fs = std::filesystem;
using namespace ccm;

namespace fields_cli_test {

struct CliResult {
  int status = -1;
  std::string err;
};

CliResult run_shell(const std::string& command, const test::TempDir& dir) {
  const fs::path err = dir.path / "stderr.txt";
  const int raw = std::system(fmt::format("{} 2> '{}'", command, err.string()).c_str());
  CliResult s;
  s.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  std::ifstream e(err);
  std::ostringstream text;
  text << e.rdbuf();
  s.err = text.str();
  return s;
}

std::string ccm_command(const std::string& args) {
  return fmt::format("'{}' {}", CCM_BINARY, args);
}

// A 1 cm cube in free flight at v0 for 1 ms: u = v0 t exactly, at every node.
const Vec3 kV0(0.3, -0.2, 0.1);
std::string flying_cube(const std::string& output) {
  std::string s = test::kOneCubeScene;
  s.insert(s.find("[bodies.material]"), "initial_velocity = [0.3, -0.2, 0.1]\n");
  return s + "[output]\n" + output;
}

// The tiny grid of the study tests: one point per model, each run well under a second.
const std::string kTinyGrid = std::string(R"([axes]
ER = [1.0]
RLS = [0.5]
KE = [0.001]
[time]
contact_time = 0.02
end = 0.03
output_interval = 1e-3
)") + std::string(test::kTinyGridBodies);

}  // namespace fields_cli_test

using namespace fields_cli_test;

TEST_CASE("ccm run: [output] fields writes fields.xdmf + fields.h5, u = v0 t read back",
          "[fields][cli]") {
  test::TempDir tmp;
  const fs::path scene = tmp.write(
      "cube.toml", flying_cube("fields = [\"displacement\", \"J\"]\nfield_interval = 2e-4\n"));
  const fs::path out = tmp.path / "out";
  const CliResult s = run_shell(
      ccm_command(fmt::format("run '{}' --out '{}' --quiet", scene.string(), out.string())), tmp);
  INFO(s.err);
  REQUIRE(s.status == 0);
  const fs::path xdmf = out / fields::kXdmfFile;
  const test::XdmfContent c = test::read_xdmf(xdmf);
  test::check_datasets(xdmf, c);
  REQUIRE(c.frames.size() == 6);  // 0, 0.2, ..., 1 ms
  CHECK(c.frames[1].attributes == std::vector<std::string>{"bodies/displacement", "bodies/J"});
  // Free flight: every node's displacement is v0 t (1e-12 relative: the round-off of ~100
  // steps x += dt v); J = 1.
  const double t = c.frames.back().time;
  CHECK(t == Approx(1e-3).epsilon(1e-12));
  const std::vector<double> u = test::read_h5_doubles(
      out / fields::kH5File, fields::frame_dataset(5, FieldKind::displacement));
  REQUIRE(u.size() % 3 == 0);
  for (size_t i = 0; i < u.size(); i += 3)
    CHECK((Vec3(u[i], u[i + 1], u[i + 2]) - kV0 * t).norm() <= 1e-12 * kV0.norm() * t);
  for (double J :
       test::read_h5_doubles(out / fields::kH5File, fields::frame_dataset(5, FieldKind::J)))
    CHECK(J == Approx(1.0).epsilon(1e-12));
}

TEST_CASE("ccm run: a bad field name is refused, nothing written", "[fields][cli]") {
  test::TempDir tmp;
  const fs::path scene = tmp.write("cube.toml", flying_cube("fields = [\"displacment\"]\n"));
  const fs::path out = tmp.path / "out";
  const CliResult s = run_shell(
      ccm_command(fmt::format("run '{}' --out '{}' --quiet", scene.string(), out.string())), tmp);
  CHECK(s.status == 2);
  CHECK_THAT(s.err, Catch::Contains(scene.string() +
                                    ":15: output.fields[0]: must be one of \"displacement\""));
  CHECK_THAT(s.err, Catch::Contains("did you mean \"displacement\"?"));
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("ccm study scene | ccm run - --fields: the study point's fields, as from a file",
          "[fields][cli]") {
  test::TempDir tmp;
  const fs::path grid = tmp.write("tiny.toml", kTinyGrid);
  const fs::path piped = tmp.path / "piped", filed = tmp.path / "filed";
  const fs::path scene = tmp.path / "p0.toml";
  REQUIRE(run_shell(ccm_command(fmt::format("study scene '{}' --point 0 > '{}'", grid.string(),
                                            scene.string())),
                    tmp)
              .status == 0);
  const CliResult p = run_shell(
      fmt::format("{} | {}", ccm_command(fmt::format("study scene '{}' --point 0", grid.string())),
                  ccm_command(fmt::format("run - --out '{}' --fields --quiet", piped.string()))),
      tmp);
  INFO(p.err);
  REQUIRE(p.status == 0);
  REQUIRE(run_shell(ccm_command(fmt::format("run '{}' --out '{}' --fields --quiet", scene.string(),
                                            filed.string())),
                    tmp)
              .status == 0);
  const test::XdmfContent c = test::read_xdmf(piped / fields::kXdmfFile);
  test::check_datasets(piped / fields::kXdmfFile, c);
  REQUIRE(c.frames.size() == 31);  // every 1 ms output sample, 0 ... 30 ms
  CHECK(c.frames[0].grids == std::vector<std::string>{"bodies", "surfaces"});
  CHECK(c.frames[0].attributes.size() == 9);  // every field
  // Same scene, same run: the same displacements, bit for bit.
  for (int k : {10, 30}) {
    const std::string u = fields::frame_dataset(k, FieldKind::displacement);
    CHECK(test::read_h5_doubles(piped / fields::kH5File, u) ==
          test::read_h5_doubles(filed / fields::kH5File, u));
  }
  std::ifstream summary(piped / "summary.toml");
  std::stringstream text;
  text << summary.rdbuf();
  CHECK_THAT(text.str(), Catch::Contains("scene = \"<stdin>\""));
  CHECK_THAT(text.str(), Catch::Contains("\n[fields]\nfile = \"fields.xdmf\"\nframes = 31\n"));
}

TEST_CASE("ccm rig run --fields: refused without --out or with an interval off the samples",
          "[fields][cli]") {
  test::TempDir tmp;
  const CliResult no_out = run_shell(ccm_command("rig run RX025 --drive physical --fields --db '" +
                                                 (tmp.path / "r.sqlite").string() + "' --quiet"),
                                     tmp);
  CHECK(no_out.status == 2);
  CHECK_THAT(no_out.err, Catch::Contains("--fields writes into the output folder: give --out DIR"));
  const CliResult off = run_shell(
      ccm_command("rig run RX025 --drive physical --fields --field-interval 7e-4 --out '" +
                  (tmp.path / "o").string() + "' --quiet"),
      tmp);
  CHECK(off.status == 2);
  CHECK_THAT(off.err,
             Catch::Contains("--field-interval 0.0007: must be a whole multiple of the output "
                             "interval 0.0005 s (got 0.0007 s)"));
  CHECK_FALSE(fs::exists(tmp.path / "o"));
  CHECK_FALSE(fs::exists(tmp.path / "r.sqlite"));
}

TEST_CASE("ccm rig run --fields: the rig's fields next to its other files",
          "[fields][cli][heavy]") {
  // The short RX025 run of the rig CLI tests (tests/rig_models/test_rig_cli.cpp): 19 ms, sampled
  // every 0.5 ms; a frame every 2.5 ms.
  test::TempDir tmp;
  const fs::path data = fs::path(CCM_SOURCE_DIR) / "tests" / "data" / "rig-dev";
  const fs::path geometry =
      fs::path(CCM_SOURCE_DIR) / "tests" / "rig_models" / "data" / "short_geometry.toml";
  const fs::path out = tmp.path / "out";
  const CliResult s =
      run_shell(ccm_command(fmt::format(
                    "rig run RX025 --data '{}' --geometry '{}' --start 0.0595 --end 0.0785 "
                    "--fields --field-interval 2.5e-3 --out '{}' --quiet",
                    data.string(), geometry.string(), out.string())),
                tmp);
  INFO(s.err);
  REQUIRE(s.status == 0);
  for (const char* f : {"channels.csv", "history.csv", "summary.toml", "fields.xdmf", "fields.h5"})
    CHECK(fs::exists(out / f));
  const test::XdmfContent c = test::read_xdmf(out / fields::kXdmfFile);
  test::check_datasets(out / fields::kXdmfFile, c);
  REQUIRE(c.frames.size() == 9);  // 0, 2.5, ..., 17.5 ms and the end, 19 ms
  CHECK(c.frames.back().time == Approx(0.019).epsilon(1e-9));
  CHECK(c.frames[0].attributes.size() == 9);
}
