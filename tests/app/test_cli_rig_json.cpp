// `ccm rig list --json` and `ccm rig run --json`: the same figures as the case file and the
// store, as one JSON document on stdout.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "db/sqlite/connection.hpp"
#include "db/sqlite/statement.hpp"
#include "rig_models/cases/case_file.hpp"
#include "tests/app/cli_shell.hpp"

namespace ccm {
namespace {

namespace fs = std::filesystem;

const fs::path kSourceCases = fs::path(CCM_SOURCE_DIR) / "rig_models" / "cases.toml";

double stored_number(db::Connection& c, const std::string& sql) {
  db::Statement q(c, sql);
  REQUIRE(q.step());
  return q.column_double(0);
}

}  // namespace

TEST_CASE("ccm rig list --json holds the case file's parameters and its 12 cases", "[cli][rig]") {
  test::TempDir dir;
  const auto r = test::run_ccm("rig list --json", dir);
  INFO(r.err);
  REQUIRE(r.status == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const rig::RigCaseTable table = rig::read_case_table(kSourceCases);
  // The default case file is the source tree's, through the build tree's data folder.
  CHECK(fs::equivalent(j["case_file"].get<std::string>(), kSourceCases));
  CHECK(j["rig"]["hanging_mass"]["value"] == table.rig.hanging_mass.value);
  CHECK(j["rig"]["hanging_mass"]["unit"] == table.rig.hanging_mass.unit);
  CHECK(j["rig"]["sensor_area"]["source"] == table.rig.sensor_area.source);
  CHECK(j["drive"]["string_stiffness"]["value"] == table.drive.string_stiffness.value);
  CHECK(j["simulation"]["output_interval"]["value"] == table.simulation.output_interval.value);
  REQUIRE(j["cases"].size() == table.cases.size());
  REQUIRE(table.cases.size() == 12);
  for (std::size_t k = 0; k < table.cases.size(); ++k) {
    const rig::RigCase& c = table.cases[k];
    const nlohmann::json& jc = j["cases"][k];
    CHECK(jc["code"] == c.code);
    CHECK(jc["number"] == c.number);
    CHECK(jc["target_speed"]["value"] == c.target_speed.value);
    CHECK(jc["impactor"] == std::string(rig::name_of(c.impactor)));
    CHECK(jc["pivot_friction"].is_null() == !c.pivot_friction.has_value());
  }
}

// [heavy]: under the sanitizers the run takes about 14 CPU-s, and the run itself is covered there
// by tests/rig_models/test_rig_cli.cpp's short runs.
TEST_CASE("ccm rig run --json prints the run and its comparison as the store holds them",
          "[cli][rig][heavy]") {
  // The SHORT variant of tests/rig_models/test_rig_cli.cpp, in its calibration window (11 ms up
  // to the measured contact, about 1 s of CPU in Release): RX025 on the dev trials, the coarse
  // test geometry.
  test::TempDir dir;
  const fs::path db = dir.path / "rig.sqlite";
  const auto r = test::run_ccm(
      "rig run RX025 --data '" + (fs::path(CCM_SOURCE_DIR) / "tests/data/rig-dev").string() +
          "' --geometry '" +
          (fs::path(CCM_SOURCE_DIR) / "tests/rig_models/data/short_geometry.toml").string() +
          "' --start 0.0595 --end 0.0705 --db '" + db.string() + "' --json",
      dir);
  INFO(r.err);
  REQUIRE(r.status == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);  // nothing but the document on stdout
  db::Connection c(db);
  CHECK(j["rig_runs_id"] == stored_number(c, "SELECT id FROM rig_runs"));
  CHECK(j["db"] == db.string());
  CHECK(j["exit_code"] == 0);
  CHECK(j["case_code"] == "RX025");
  CHECK(j["drive"] == "open-loop");
  CHECK(j["drive_trial"]["trial"] == 2);
  CHECK(j["run"]["status"] == "completed");
  CHECK(j["run"]["steps"] == stored_number(c, "SELECT steps FROM rig_runs"));
  CHECK(j["run"]["max_energy_error"].get<double>() ==
        stored_number(c, "SELECT max_energy_error FROM rig_runs"));
  CHECK(j["window"]["start"].get<double>() == Approx(0.0595));
  CHECK(j["model"]["n_elements"] == stored_number(c, "SELECT n_elements FROM rig_runs"));
  // The Fixed artifact hangs on its clamp, as cases.toml gives it, without friction.
  const rig::RigCaseTable table = rig::read_case_table(kSourceCases);
  CHECK(j["model"]["clamp_stiffness"].get<double>() == table.rig.clamp_stiffness.value);
  CHECK(j["model"]["clamp_damping"].get<double>() == table.rig.clamp_damping.value);
  CHECK(j["model"]["frictional_pin"] == false);
  const nlohmann::json& cmp = j["comparison"];
  CHECK(cmp["scored_trials"] == nlohmann::json({1, 3}));
  CHECK(cmp["left_out_trial"] == 2);
  for (const char* channel : {"velocity", "angle", "pressure"}) {
    INFO(channel);
    const nlohmann::json& per_trial = cmp["channels"][channel]["per_trial"];
    REQUIRE(per_trial.size() == 2);
    for (const nlohmann::json& t : per_trial)
      CHECK(t["rmse"].get<double>() ==
            stored_number(c, "SELECT rmse FROM rig_channel_metrics WHERE channel = '" +
                                 std::string(channel) +
                                 "' AND trial = " + std::to_string(t["trial"].get<int>())));
  }
}

TEST_CASE("ccm rig run: a rig.toml beside the trials sets their sensor's area and deadband",
          "[cli][rig][rig_file][heavy]") {
  // The dev trials copied with a rig file: a 30 x 30 mm sensor patch and a 74 kPa deadband. The
  // run meshes the smaller patch (its mesh area within a tenth of the given one: the patch is
  // the envelope's triangles whose centroids fall inside it) and reads the measured contact
  // onset at the higher threshold (above trial 2's first contact sample, 72.8 kPa), one sample
  // later than at the case file's 1 kPa.
  test::TempDir dir;
  const fs::path data = dir.path / "trials";
  fs::create_directories(data);
  for (const auto& e : fs::directory_iterator(fs::path(CCM_SOURCE_DIR) / "tests/data/rig-dev"))
    if (e.path().extension() == ".csv") fs::copy_file(e.path(), data / e.path().filename());
  const std::string run =
      "rig run RX025 --geometry '" +
      (fs::path(CCM_SOURCE_DIR) / "tests/rig_models/data/short_geometry.toml").string() +
      "' --start 0.0595 --end 0.0705 --json --data '" + data.string() + "'";
  const auto plain = test::run_ccm(run + " --db '" + (dir.path / "a.sqlite").string() + "'", dir);
  INFO(plain.err);
  REQUIRE(plain.status == 0);
  dir.write("trials/rig.toml",
            "[rig]\nsensor_area = { value = 9e-4, unit = \"m^2\", source = \"30 mm mat\" }\n"
            "sensor_deadband = { value = 74.0, unit = \"kPa\", source = \"threshold\" }\n");
  const auto r = test::run_ccm(run + " --db '" + (dir.path / "b.sqlite").string() + "'", dir);
  INFO(r.err);
  REQUIRE(r.status == 0);
  const nlohmann::json a = nlohmann::json::parse(plain.out), b = nlohmann::json::parse(r.out);
  CHECK(b["model"]["sensor_area"].get<double>() == 9e-4);
  CHECK(b["model"]["sensor_mesh_area"].get<double>() == Approx(9e-4).epsilon(0.1));
  CHECK(a["model"]["sensor_mesh_area"].get<double>() > 1.3e-3);
  CHECK(b["window"]["measured_onset"].get<double>() > a["window"]["measured_onset"].get<double>());
  // A defect in the rig file is refused before any run, naming it.
  dir.write("trials/rig.toml", "[rig]\nsensor_area = 1.0\n");
  const auto bad = test::run_ccm(run + " --db '" + (dir.path / "c.sqlite").string() + "'", dir);
  CHECK(bad.status == 2);
  CHECK(bad.err.find("rig.toml:2: rig.sensor_area") != std::string::npos);
  CHECK_FALSE(fs::exists(dir.path / "c.sqlite"));
}

TEST_CASE("ccm rig run: through the sensor mat the blow reads a pressure and lasts longer",
          "[cli][rig][sensor_mat][heavy]") {
  // RX025 in the short geometry, 19 ms around the contact, three times: the exact contact, and
  // the mat at two stiffnesses. The mat's pressure is its force over the patch (eq. 3.8); a
  // softer mat (a quarter of the stiffness) stretches the pulse: a lower peak (its impulse
  // against the momentum: tests/rig_models/sim/test_sensor_mat.cpp).
  test::TempDir dir;
  const std::string run =
      "rig run RX025 --data '" + (fs::path(CCM_SOURCE_DIR) / "tests/data/rig-dev").string() +
      "' --geometry '" +
      (fs::path(CCM_SOURCE_DIR) / "tests/rig_models/data/short_geometry.toml").string() +
      "' --start 0.0595 --end 0.0785 --json";
  std::vector<nlohmann::json> out;
  for (const std::string set : {"", " --set mat_stiffness=4e4", " --set mat_stiffness=1e4"}) {
    const auto r =
        test::run_ccm(run + set + " --db '" +
                          (dir.path / (std::to_string(out.size()) + ".sqlite")).string() + "'",
                      dir);
    INFO(set << ": " << r.err);
    REQUIRE(r.status == 0);
    out.push_back(nlohmann::json::parse(r.out));
  }
  const auto peak = [](const nlohmann::json& j) {
    return j["comparison"]["channels"]["pressure"]["per_trial"][0]["peak_simulated"].get<double>();
  };
  CHECK(peak(out[1]) > 0.0);
  CHECK(peak(out[2]) < peak(out[1]));
  CHECK(out[1]["parameters"].get<std::string>().find("mat_stiffness=40000") != std::string::npos);
  CHECK(out[0]["parameters"].get<std::string>().find("mat_stiffness=0") != std::string::npos);
}

}  // namespace ccm
