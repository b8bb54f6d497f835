// Reading a folder of trials before any simulation: grouped by case in trial order; a repeated
// trial, an empty or missing folder refused by name.
#include <fmt/format.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "rig_models/core/rig_error.hpp"
#include "rig_models/measurement/trial_folder.hpp"

namespace fs = std::filesystem;
using namespace ccm::rig;

namespace {

std::string trial_text(const std::string& header) {
  return header +
         "time_s,impactor_velocity_mps,artifact_angle_deg,pressure_kpa\n"
         "0.0,0.1,0.0,0\n";
}

std::string error_of(const fs::path& folder) {
  try {
    read_trial_folder(folder);
  } catch (const RigInputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("trial folder: grouped by case, in trial order, repeats and empty folders refused",
          "[rig]") {
  const fs::path dir = fs::temp_directory_path() / fmt::format("ccm-test-rig-folder-{}", getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "RX025_t2.csv") << trial_text("");
  std::ofstream(dir / "RX025_t1.csv") << trial_text("");
  std::ofstream(dir / "FF100_t1.csv") << trial_text("");
  std::ofstream(dir / "notes.txt") << "not a trial";
  const auto by_case = read_trial_folder(dir);
  REQUIRE(by_case.size() == 2);
  REQUIRE(by_case.at("RX025").size() == 2);
  CHECK(by_case.at("RX025")[0].trial == 1);
  CHECK(by_case.at("RX025")[1].trial == 2);
  CHECK(by_case.at("FF100")[0].trial == 1);

  std::ofstream(dir / "copy.csv") << trial_text("# case: RX025\n# trial: 2\n");
  CHECK(error_of(dir) == fmt::format("{}: trial 2 of RX025 is also in {}",
                                     (dir / "copy.csv").string(), (dir / "RX025_t2.csv").string()));
  fs::remove(dir / "copy.csv");
  std::ofstream(dir / "loose.csv") << trial_text("# case: RF050\n");
  CHECK(error_of(dir) ==
        fmt::format("{}: no trial number: add '# trial: <N>' or name the file <CASE>_t<N>.csv",
                    (dir / "loose.csv").string()));

  fs::remove_all(dir);
  fs::create_directories(dir);
  CHECK(error_of(dir) == dir.string() + ": no measured trial (*.csv) here");
  fs::remove_all(dir);
  CHECK(error_of(dir) == dir.string() + ": cannot list the folder: No such file or directory");
}
