// One-off: the rig's comparison of the 12 dev cases before it goes through the bench path.
#include <catch2/catch.hpp>
#include <fstream>

#include "config/text_file.hpp"
#include "rig_models/cases/case_file.hpp"
#include "rig_models/measurement/trial_folder.hpp"
#include "rig_models/post/rig_channels.hpp"
#include "tests/bench_test/rig_case_rows.hpp"

TEST_CASE("generate the rig comparison fixture", "[.generate]") {
  namespace fs = std::filesystem;
  const fs::path root(CCM_SOURCE_DIR);
  const auto table = ccm::rig::parse_case_table(
      ccm::read_config_text(root / "rig_models/cases.toml"), root / "rig_models/cases.toml");
  const auto by_case = ccm::rig::read_trial_folder(root / "tests/data/rig-dev");
  const ccm::rig::PressureSensor sensor{table.rig.sensor_deadband.value,
                                        table.rig.low_pass_cutoff.value};
  std::ofstream out(root / "tests/data/rig-comparison-before-bench-path.csv");
  out << "case,item,trial,field,value\n";
  for (const auto& [code, trials] : by_case) {
    const auto raw = ccm::test::raw_curves_from(trials.at(1));
    const auto scored = ccm::rig::scored_trials(trials, 2);
    const ccm::rig::RigChannels sensed{
        raw.velocity_mps, raw.angle_deg,
        ccm::rig::sensed_pressure_kpa(raw.pressure_raw_kpa, sensor, raw.pressure_raw_kpa.t)};
    for (const std::string& row : ccm::test::comparison_rows(
             code, ccm::rig::compare_case(scored, sensed, sensor.deadband_kpa)))
      out << row << "\n";
  }
}
