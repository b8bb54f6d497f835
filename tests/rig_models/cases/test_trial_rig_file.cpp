// A rig file beside the measured trials (rig_models/cases/trial_rig_file.hpp): its [rig] keys
// replace the case file's, checked as there, naming the file, the line and the key; without one
// the case file stands; the geometry's sensor patch takes the trials' area.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <string>

#include "rig_models/cases/case_file.hpp"
#include "rig_models/cases/trial_rig_file.hpp"
#include "rig_models/core/rig_error.hpp"
#include "rig_models/geometry/geometry_file.hpp"
#include "tests/support/temp_dir.hpp"

using namespace ccm;
using namespace ccm::rig;

namespace {

const std::filesystem::path kShippedCases =
    std::filesystem::path(CCM_SOURCE_DIR) / "rig_models/cases.toml";
const std::filesystem::path kShippedGeometry =
    std::filesystem::path(CCM_SOURCE_DIR) / "rig_models/geometry.toml";

void write_file(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

std::string rig_file_error(const std::string& text) {
  test::TempDir dir;
  write_file(dir.path / kTrialRigFileName, text);
  RigParameters rig = read_case_table(kShippedCases).rig;
  try {
    apply_trial_rig_file(dir.path, rig);
  } catch (const RigInputError& e) {
    return e.what();
  }
  return "(accepted)";
}

}  // namespace

TEST_CASE("trial rig file: the trials' sensor replaces the case file's, the rest stands",
          "[rig][rig_file]") {
  test::TempDir dir;
  const RigParameters cases = read_case_table(kShippedCases).rig;
  RigParameters rig = cases;
  CHECK_FALSE(apply_trial_rig_file(dir.path, rig));  // no file: the case file's values
  CHECK(rig.sensor_area.value == cases.sensor_area.value);
  const std::string text =
      "[rig]\nsensor_area = { value = 1.0e-3, unit = \"m^2\", source = \"our 32 mm mat\" }\n"
      "sensor_deadband = { value = 0.5, unit = \"kPa\", source = \"logger threshold\" }\n";
  write_file(dir.path / kTrialRigFileName, text);
  const auto file = apply_trial_rig_file(dir.path, rig);
  REQUIRE(file);
  CHECK(file->text == text);
  CHECK(rig.sensor_area.value == 1.0e-3);
  CHECK(rig.sensor_area.source == "our 32 mm mat");
  CHECK(rig.sensor_deadband.value == 0.5);
  CHECK(rig.hanging_mass.value == cases.hanging_mass.value);
  CHECK(rig.clamp_stiffness.value == cases.clamp_stiffness.value);
  // The geometry's patch keeps its aspect and takes the area; the model then agrees with it.
  RigGeometry g = read_geometry(kShippedGeometry);
  const double aspect = g.artifact.sensor_width.value / g.artifact.sensor_height.value;
  fit_sensor_patch(g, rig.sensor_area.value);
  CHECK(g.artifact.sensor_width.value * g.artifact.sensor_height.value ==
        Approx(1.0e-3).epsilon(1e-12));
  CHECK(g.artifact.sensor_width.value / g.artifact.sensor_height.value ==
        Approx(aspect).epsilon(1e-12));
  CHECK_NOTHROW(check_against_cases(g, rig));
  // A patch too wide for the envelope's struck half is refused before any run.
  rig.sensor_area.value = 4e-3;
  fit_sensor_patch(g, rig.sensor_area.value);
  CHECK_THROWS_WITH(check_against_cases(g, rig), Catch::Contains("must fit on the struck half"));
}

TEST_CASE("trial rig file: what the case file refuses is refused with file, line and key",
          "[rig][rig_file]") {
  using Catch::Contains;
  CHECK_THAT(
      rig_file_error("[rig]\nsensor_area = { value = -1.0, unit = \"m^2\", source = \"x\" }\n"),
      Contains("rig.toml:2") && Contains("rig.sensor_area.value") && Contains("> 0"));
  CHECK_THAT(
      rig_file_error("[rig]\nsensor_deadband = { value = 1.0, unit = \"Pa\", source = \"x\" }\n"),
      Contains("rig.sensor_deadband.unit") && Contains("must be 'kPa'"));
  CHECK_THAT(
      rig_file_error("[rig]\nsensor_aera = { value = 1.0, unit = \"m^2\", source = \"x\" }\n"),
      Contains("rig.toml:2") && Contains("sensor_aera") && Contains("sensor_area"));
  CHECK_THAT(rig_file_error("[sensor]\narea = 1.0\n"),
             Contains("rig.toml:1") && Contains("sensor"));
  CHECK_THAT(
      rig_file_error("[rig]\nlow_pass_cutoff = { value = 100.0, unit = \"Hz\", source = \"x\" }\n"),
      Contains("low_pass_cutoff") && Contains("Nyquist"));
  CHECK_THAT(rig_file_error("[rig\n"), Contains("rig.toml:1"));
}
