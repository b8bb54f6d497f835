// ParaView opens the field output (docs/fields.md): the example ball-on-plate scene is run with
// fields, then pvbatch (python3-paraview) under a virtual X server of its own
// (tests/io/fields/headless.sh: Debian's ParaView renders through X11, it has no EGL or OSMesa
// build) reads it with its XDMF 3 reader
// (tests/io/fields/paraview_field.py), and what it read is compared with the HDF5 file, exactly,
// and renders one screenshot. Fails, never skips, when pvbatch or Xvfb is missing
// (scripts/install-deps.sh installs them). With CCM_UPDATE_DOC_IMAGES=1 in the environment the
// screenshot is also copied to docs/images/paraview-field.png (the figure of docs/fields.md).
#include <fmt/format.h>
#include <sys/wait.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "io/fields/field_recorder.hpp"
#include "io/fields/xdmf_text.hpp"
#include "tests/io/fields/field_files_check.hpp"
#include "tests/reports/png_size.hpp"
#include "tests/support/temp_dir.hpp"

namespace fs = std::filesystem;
using namespace ccm;

namespace paraview_test {

int system_status(const std::string& command) {
  const int raw = std::system(command.c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

bool have(const char* tool) {
  return system_status(fmt::format("command -v {} > /dev/null 2>&1", tool)) == 0;
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The example scene with three fields every millisecond (11 frames) in its [output] table.
std::string example_with_fields() {
  std::string s =
      read_text(fs::path(CCM_SOURCE_DIR) / "scenes" / "examples" / "ball_on_plate_dcr.toml");
  const size_t at = s.find("\n[output]\n");
  REQUIRE(at != std::string::npos);
  s.insert(at + 10,
           "fields = [\"displacement\", \"von_mises\", \"contact_pressure\"]\n"
           "field_interval = 1e-3\n");
  return s;
}

}  // namespace paraview_test

using namespace paraview_test;

TEST_CASE("ParaView opens the field output, reads the values ccm wrote, renders it headless",
          "[fields][paraview][heavy]") {
  REQUIRE(have("pvbatch"));  // python3-paraview
  REQUIRE(have("Xvfb"));     // xvfb
  test::TempDir tmp;
  const fs::path scene = tmp.write("ball.toml", example_with_fields());
  const fs::path out = tmp.path / "out", png = tmp.path / "paraview-field.png";
  REQUIRE(system_status(fmt::format("'{}' run '{}' --out '{}' --quiet", CCM_BINARY, scene.string(),
                                    out.string())) == 0);
  const fs::path xdmf = out / fields::kXdmfFile, h5 = out / fields::kH5File;
  const int frame = 3;
  const fs::path log = tmp.path / "pvbatch.txt";
  const fs::path here = fs::path(CCM_SOURCE_DIR) / "tests" / "io" / "fields";
  const std::string pvbatch = fmt::format(
      "'{}' pvbatch '{}' '{}' {} '{}' > '{}' 2>&1", (here / "headless.sh").string(),
      (here / "paraview_field.py").string(), xdmf.string(), frame, png.string(), log.string());
  // Up to three attempts, each with a fresh X server: on the shared, loaded build machine about
  // one pvbatch in three started at the same moment failed to open its (running, ready) display
  // ("bad X server connection"); the cause was not found. A missing tool still fails at once.
  int status = -1;
  for (int attempt = 0; attempt < 3 && status != 0; ++attempt) status = system_status(pvbatch);
  const std::string printed = read_text(log);
  INFO(printed);
  REQUIRE(status == 0);

  const size_t at = printed.find("CCM_PARAVIEW {");
  REQUIRE(at != std::string::npos);
  const nlohmann::json read =
      nlohmann::json::parse(printed.substr(at + 13, printed.find('\n', at) - at - 13));
  // The times, the displacement of node 0 and the largest von Mises stress at the frame: what
  // the HDF5 file holds, exactly (ParaView reads the doubles and Python prints them round-trip).
  CHECK(read["times"].get<std::vector<double>>() ==
        test::read_h5_doubles(h5, fields::kTimeDataset));
  const std::vector<double> u =
      test::read_h5_doubles(h5, fields::frame_dataset(frame, FieldKind::displacement));
  CHECK(read["u_node0"].get<std::vector<double>>() ==
        std::vector<double>(u.begin(), u.begin() + 3));
  const std::vector<double> vm =
      test::read_h5_doubles(h5, fields::frame_dataset(frame, FieldKind::von_mises));
  CHECK(read["von_mises_max"].get<double>() == *std::max_element(vm.begin(), vm.end()));
  CHECK(read["point_arrays"] == nlohmann::json({"displacement"}));
  CHECK(read["cell_arrays"] == nlohmann::json({"contact_pressure", "von_mises"}));

  // The screenshot: 960 x 600, and not blank (a uniform image compresses to a few hundred bytes).
  const auto summary = test::summarise_png(png);
  REQUIRE(summary);
  CHECK(summary->width == 960);
  CHECK(summary->height == 600);
  CHECK(summary->idat_bytes > 20000);
  if (const char* update = std::getenv("CCM_UPDATE_DOC_IMAGES");
      update && std::string(update) == "1")
    fs::copy_file(png, fs::path(CCM_SOURCE_DIR) / "docs" / "images" / "paraview-field.png",
                  fs::copy_options::overwrite_existing);
}
