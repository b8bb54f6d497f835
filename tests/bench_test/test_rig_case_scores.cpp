// The rig's cases as bench tests (bench_test/rig_case_scores.hpp): the mapping reads the rig's own
// CSV layout as the rig's reader does, and the rig's comparison through the bench path equals the
// rig's own comparison before it went through it (tests/data/rig-comparison-before-bench-path.md),
// on all 12 cases.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "bench_test/bench_scores.hpp"
#include "bench_test/rig_case_scores.hpp"
#include "config/text_file.hpp"
#include "rig_models/cases/case_file.hpp"
#include "rig_models/measurement/trial_folder.hpp"
#include "tests/app/cli_shell.hpp"
#include "tests/bench_test/rig_case_rows.hpp"
#include "tests/support/temp_dir.hpp"

namespace fs = std::filesystem;
using namespace ccm;

namespace {

const fs::path kRoot(CCM_SOURCE_DIR);

rig::PressureSensor default_sensor() {
  const auto table = rig::parse_case_table(read_config_text(kRoot / "rig_models/cases.toml"),
                                           kRoot / "rig_models/cases.toml");
  return {table.rig.sensor_deadband.value, table.rig.low_pass_cutoff.value};
}

// "case,item,trial,field" -> value, of the fixture's rows or of rows made now.
std::map<std::string, double> keyed(const std::vector<std::string>& rows) {
  std::map<std::string, double> out;
  for (const std::string& row : rows) {
    const std::size_t at = row.rfind(',');
    out[row.substr(0, at)] = std::stod(row.substr(at + 1));
  }
  return out;
}

std::vector<std::string> fixture_rows() {
  std::ifstream in(kRoot / "tests/data/rig-comparison-before-bench-path.csv");
  REQUIRE(in);
  std::vector<std::string> rows;
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line))
    if (!line.empty()) rows.push_back(line);
  return rows;
}

}  // namespace

TEST_CASE("rig as bench test: the mapping reads the rig's CSV layout as the rig's reader does",
          "[bench_test]") {
  const rig::PressureSensor sensor = default_sensor();
  const auto by_case = rig::read_trial_folder(kRoot / "tests/data/rig-dev");
  for (const auto& [code, trials] : by_case) {
    INFO(code);
    const bench::BenchMapping m = bench::parse_bench_mapping(
        bench::rig_case_mapping_text(code, sensor), kRoot / "tests/data/rig-dev/bench.toml");
    const std::vector<bench::BenchTrial> read = bench::read_bench_trials(m);
    REQUIRE(read.size() == trials.size());
    for (std::size_t i = 0; i < read.size(); ++i) {
      const bench::BenchTrial expected = bench::bench_trial_of(trials[i], m, i);
      CHECK(read[i].file.filename() == trials[i].source.filename());
      for (const auto& [name, series] : expected.channels) {
        CHECK(read[i].channels.at(name).t == series.t);
        CHECK(read[i].channels.at(name).value == series.value);
      }
    }
  }
}

TEST_CASE("rig as bench test: the 12 cases score as the rig's own comparison did", "[bench_test]") {
  // Tolerance: the bench path works in SI (deg to rad, kPa to Pa and back) and the rig's did
  // not: the scores agree to round-off, 1e-12 relative (1e-15 absolute for values near zero).
  const rig::PressureSensor sensor = default_sensor();
  const auto by_case = rig::read_trial_folder(kRoot / "tests/data/rig-dev");
  REQUIRE(by_case.size() == 12);
  std::vector<std::string> rows;
  for (const auto& [code, trials] : by_case) {
    const test::RawCurves raw = test::raw_curves_from(trials.at(1));
    const auto scored = rig::scored_trials(trials, 2);
    const rig::CaseComparison c = bench::score_rig_case(
        code, scored, {raw.velocity_mps, raw.angle_deg, raw.pressure_raw_kpa}, sensor);
    for (std::string& r : test::comparison_rows(code, c)) rows.push_back(std::move(r));
  }
  const std::map<std::string, double> before = keyed(fixture_rows());
  const std::map<std::string, double> now = keyed(rows);
  REQUIRE(before.size() == 1252);
  CHECK(now.size() == before.size());
  for (const auto& [key, value] : before) {
    INFO(key);
    REQUIRE(now.count(key) == 1);
    CHECK(std::abs(now.at(key) - value) <= 1e-12 * std::abs(value) + 1e-15);
  }
}

TEST_CASE("ccm rig mapping: prints the case's mapping, which reads the case's trials",
          "[bench_test][cli]") {
  test::TempDir dir;
  const auto r = test::run_ccm("rig mapping FX050", dir);
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(r.out == bench::rig_case_mapping_text("FX050", default_sensor()));
  // Beside the trials, as a user would put it: the mapping reads FX050's three trials.
  const bench::BenchMapping m =
      bench::parse_bench_mapping(r.out, kRoot / "tests/data/rig-dev/bench.toml");
  CHECK(bench::read_bench_trials(m).size() == 3);
  const auto bad = test::run_ccm("rig mapping FX051", dir);
  CHECK(bad.status == 2);
  CHECK(bad.err.find("'FX051' is not a case") != std::string::npos);
}
