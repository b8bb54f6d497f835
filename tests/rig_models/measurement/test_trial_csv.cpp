// The measured-CSV reader (docs/measurements.md): a good file gives one
// series per sensor; every defect class of the spec is refused with the exact message, naming
// file, line and column.
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "rig_models/core/rig_error.hpp"
#include "rig_models/measurement/clock_jump.hpp"
#include "rig_models/measurement/trial_csv.hpp"

namespace fs = std::filesystem;
using namespace ccm::rig;

namespace {

// A valid trial; line numbers are relied upon below (header on line 3, rows on 4-7).
const std::string kGood =
    "# case: RX025\n"
    "# trial: 2\n"
    "time_s,impactor_velocity_mps,artifact_angle_deg,pressure_kpa\n"
    "0.000,0.10,0.00,0\n"
    "0.0078125,,0.01,0\n"
    "0.010,0.12,,\n"
    "0.015625,,0.02,1.5\n";

const fs::path kName = "RX025_t2.csv";

std::string with(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

std::string error_of(const std::string& text, const fs::path& name = kName) {
  try {
    parse_trial_csv(text, name);
  } catch (const RigInputError& e) {
    return e.what();
  }
  return "no error";
}

void check_good_channels(const MeasuredTrial& m) {
  CHECK(m.case_code == "RX025");
  CHECK(m.trial == 2);
  CHECK(m.impactor_velocity_mps.t == std::vector<double>{0.0, 0.010});
  CHECK(m.impactor_velocity_mps.value == std::vector<double>{0.10, 0.12});
  CHECK(m.artifact_angle_deg.t == std::vector<double>{0.0, 0.0078125, 0.015625});
  CHECK(m.artifact_angle_deg.value == std::vector<double>{0.0, 0.01, 0.02});
  CHECK(m.pressure_kpa.t == std::vector<double>{0.0, 0.0078125, 0.015625});
  CHECK(m.pressure_kpa.value == std::vector<double>{0.0, 0.0, 1.5});
}

}  // namespace

TEST_CASE("trial CSV: a good file gives one series per sensor, empty cells skipped", "[rig]") {
  const MeasuredTrial m = parse_trial_csv(kGood, kName);
  check_good_channels(m);
  CHECK(m.metadata.at("case") == "RX025");
  CHECK(m.warnings.empty());
}

TEST_CASE("trial CSV: CRLF line endings, a UTF-8 BOM and blank lines are accepted", "[rig]") {
  std::string crlf = "\xEF\xBB\xBF";
  for (char c : kGood) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  crlf += "\r\n";
  check_good_channels(parse_trial_csv(crlf, kName));
}

TEST_CASE("trial CSV: columns in any order, an unknown column is ignored with a warning", "[rig]") {
  const std::string text =
      "# case: RX025\n"
      "# trial: 2\n"
      "pressure_kpa,time_s,artifact_angle_deg,impactor_velocity_mps,temperature_c\n"
      "0,0.000,0.00,0.10,21\n"
      "0,0.0078125,0.01,,21\n"
      ",0.010,,0.12,\n"
      "1.5,0.015625,0.02,,21\n";
  const MeasuredTrial m = parse_trial_csv(text, kName);
  check_good_channels(m);
  REQUIRE(m.warnings.size() == 1);
  CHECK(m.warnings[0] == "RX025_t2.csv:3: column 5 (temperature_c): unknown column, ignored");
}

TEST_CASE("trial CSV: the case and trial come from the file name when the metadata is silent",
          "[rig]") {
  const std::string text = kGood.substr(kGood.find("time_s"));
  const MeasuredTrial m = parse_trial_csv(text, "data/FF100_t3.csv");
  CHECK(m.case_code == "FF100");
  CHECK(m.trial == 3);
}

TEST_CASE("trial CSV: a non-numeric cell", "[rig]") {
  CHECK(error_of(with(kGood, "0.0078125,,0.01,0", "0.0078125,,abc,0")) ==
        "RX025_t2.csv:5: column 3 (artifact_angle_deg): non-numeric cell 'abc'");
  CHECK(error_of(with(kGood, "0.010,0.12,,", "0.010,0.12x,,")) ==
        "RX025_t2.csv:6: column 2 (impactor_velocity_mps): non-numeric cell '0.12x'");
  // a decimal comma splits the cell: the row then has too many cells
  CHECK(error_of(with(kGood, "0.010,0.12,,", "0.010,0,12,,")) ==
        "RX025_t2.csv:6: 5 cells, the header has 4");
}

TEST_CASE("trial CSV: a non-finite number", "[rig]") {
  CHECK(error_of(with(kGood, "0.015625,,0.02,1.5", "0.015625,,0.02,nan")) ==
        "RX025_t2.csv:7: column 4 (pressure_kpa): non-finite number 'nan'");
  CHECK(error_of(with(kGood, "0.015625,,0.02,1.5", "0.015625,,-inf,1.5")) ==
        "RX025_t2.csv:7: column 3 (artifact_angle_deg): non-finite number '-inf'");
  CHECK(error_of(with(kGood, "0.015625,,0.02,1.5", "0.015625,,0.02,1e999")) ==
        "RX025_t2.csv:7: column 4 (pressure_kpa): non-finite number '1e999'");
  CHECK(error_of(with(kGood, "0.015625,,0.02,1.5", "0.015625,,1e-400,1.5")) ==
        "RX025_t2.csv:7: column 3 (artifact_angle_deg): number '1e-400' is too small for a "
        "double");
  CHECK(error_of(with(kGood, "0.000,0.10", "inf,0.10")) ==
        "RX025_t2.csv:4: column 1 (time_s): non-finite number 'inf'");
}

TEST_CASE("trial CSV: time going backwards or repeating", "[rig]") {
  CHECK(error_of(with(kGood, "0.010,0.12,,", "0.005,0.12,,")) ==
        "RX025_t2.csv:6: column 1 (time_s): time goes backwards: 0.005 s after 0.0078125 s "
        "(line 5)");
  CHECK(error_of(with(kGood, "0.010,0.12,,", "0.0078125,0.12,,")) ==
        "RX025_t2.csv:6: column 1 (time_s): time 0.0078125 s repeats the previous row's "
        "(line 5)");
  CHECK(error_of(with(kGood, "0.010,0.12,,", ",0.12,,")) ==
        "RX025_t2.csv:6: column 1 (time_s): empty time cell");
}

TEST_CASE("trial CSV: a forward jump of the clock (a logger glitch) is refused", "[rig]") {
  // 40 rows every 10 ms, then the logger's clock jumps by +1000 s from the 31st row (line 34:
  // two metadata lines and the header come first) and runs on.
  std::string text =
      "# case: RX025\n# trial: 2\n"
      "time_s,impactor_velocity_mps,artifact_angle_deg,pressure_kpa\n";
  for (int k = 0; k < 40; ++k)
    text += fmt::format("{},0.1,0.0,0\n", 0.01 * k + (k >= 30 ? 1000.0 : 0.0));
  CHECK(error_of(text) ==
        "RX025_t2.csv:34: column 1 (time_s): time jumps by 1000.01 s, from 0.29 s (line 33) to "
        "1000.3 s: 1e+05 times the file's median step between rows (0.01 s; the limit is 100 "
        "times). A logger clock glitch? Correct the timestamps or cut the file at the jump");
  // Without the glitch the same file is good; a gap of 50 missed samples (0.5 s) is a dropout,
  // not a glitch: it stays under the limit and is read.
  std::string dropout = "time_s,impactor_velocity_mps,artifact_angle_deg,pressure_kpa\n";
  for (int k = 0; k < 40; ++k)
    dropout += fmt::format("{},0.1,0.0,0\n", 0.01 * k + (k >= 30 ? 0.5 : 0.0));
  CHECK(parse_trial_csv(dropout, kName).pressure_kpa.t.size() == 40);
}

TEST_CASE("clock jump: the first step beyond the factor times the median row step", "[rig]") {
  // Steps 1, 1, 2, 1, 250, 1: median 1; 250 > 100 (row 5); at a factor of 300 none.
  const std::vector<double> t = {0.0, 1.0, 2.0, 4.0, 5.0, 255.0, 256.0};
  const auto jump = find_clock_jump(t);
  REQUIRE(jump);
  CHECK(jump->row == 5);
  CHECK(jump->step == 250.0);
  CHECK(jump->median_step == 1.0);
  CHECK_FALSE(find_clock_jump(t, 300.0));
  // Multi-rate rows (100 Hz and 128 Hz merged, as in the dev trials) are far from the limit.
  std::vector<double> merged;
  for (int k = 0; k <= 60; ++k) merged.push_back(0.01 * k);
  for (int k = 1; k <= 76; ++k) merged.push_back(k / 128.0);
  std::sort(merged.begin(), merged.end());
  merged.erase(std::unique(merged.begin(), merged.end()), merged.end());
  CHECK_FALSE(find_clock_jump(merged, 10.0));
  CHECK_FALSE(find_clock_jump(std::vector<double>{0.0, 1000.0}));  // two rows: no median
}

TEST_CASE("trial CSV: an empty or header-only file", "[rig]") {
  CHECK(error_of("") == "RX025_t2.csv: empty file: no header line and no data rows");
  CHECK(error_of("# case: RX025\n\n# trial: 2\r\n") ==
        "RX025_t2.csv: empty file: no header line and no data rows");
  CHECK(error_of(kGood.substr(0, kGood.find("0.000,"))) ==
        "RX025_t2.csv:3: header only: no data rows");
}

TEST_CASE("trial CSV: a wrong delimiter", "[rig]") {
  const std::string semicolons =
      "# case: RX025\n"
      "time_s;impactor_velocity_mps;artifact_angle_deg;pressure_kpa\n"
      "0.000;0.10;0.00;0\n";
  CHECK(error_of(semicolons) == "RX025_t2.csv:2: column 1: wrong delimiter ';' (expected ',')");
  const std::string tabs =
      "time_s\timpactor_velocity_mps\tartifact_angle_deg\tpressure_kpa\n"
      "0.000\t0.10\t0.00\t0\n";
  CHECK(error_of(tabs) == "RX025_t2.csv:1: column 1: wrong delimiter '\\t' (expected ',')");
  CHECK(error_of(with(kGood, "0.010,0.12,,", "0.010,0.12;,")) ==
        "RX025_t2.csv:6: column 2 (impactor_velocity_mps): wrong delimiter ';' (expected ',')");
}

TEST_CASE("trial CSV: a missing, repeated or empty column, a row of the wrong width", "[rig]") {
  CHECK(error_of(with(kGood, ",pressure_kpa\n", ",pressure\n")) ==
        "RX025_t2.csv:3: header: missing required column 'pressure_kpa' (found: time_s, "
        "impactor_velocity_mps, artifact_angle_deg, pressure)");
  CHECK(error_of(with(kGood, ",pressure_kpa\n", ",time_s\n")) ==
        "RX025_t2.csv:3: column 4 (time_s): repeats an earlier column");
  CHECK(error_of(with(kGood, "0.0078125,,0.01,0", "0.0078125,,0.01")) ==
        "RX025_t2.csv:5: 3 cells, the header has 4");
  CHECK(error_of(with(kGood, "0.0078125,,0.01,0", "0.0078125,,,")) ==
        "RX025_t2.csv:5: no sensor value at 0.0078125 s (every sensor cell is empty)");
  const std::string no_pressure =
      "time_s,impactor_velocity_mps,artifact_angle_deg,pressure_kpa\n"
      "0.000,0.10,0.00,\n"
      "0.010,0.12,0.01,\n";
  CHECK(error_of(no_pressure) == "RX025_t2.csv:1: column 4 (pressure_kpa): no value in any row");
}

TEST_CASE("trial CSV: metadata that disagrees with the file name is refused", "[rig]") {
  CHECK(error_of(with(kGood, "# case: RX025", "# case: RX050")) ==
        "RX025_t2.csv:1: case: 'RX050' but the file name says 'RX025'");
  CHECK(error_of(with(kGood, "# case: RX025", "# case: RX026")) ==
        "RX025_t2.csv:1: case: 'RX026' is not a case code of thesis Table 3.2 (RX025 ... "
        "FF100)");
  CHECK(error_of(with(kGood, "# trial: 2", "# trial: 3")) ==
        "RX025_t2.csv:2: trial: 3 but the file name says 2");
  CHECK(error_of(with(kGood, "# trial: 2", "# trial: two")) ==
        "RX025_t2.csv:2: trial: 'two' is not a positive integer");
  CHECK(error_of(kGood.substr(kGood.find("time_s")), "trial.csv") ==
        "trial.csv: no case code: add '# case: <CODE>' or name the file <CASE>_t<N>.csv");
}

TEST_CASE("trial CSV: a file that cannot be read, a file read from disk", "[rig]") {
  const fs::path dir = fs::temp_directory_path() / fmt::format("ccm-test-rig-csv-{}", getpid());
  fs::create_directories(dir);
  const fs::path missing = dir / "RX025_t9.csv";
  try {
    read_trial_csv(missing);
    FAIL("no error");
  } catch (const RigInputError& e) {
    CHECK(std::string(e.what()) == missing.string() + ": cannot open the file for reading");
  }
  const fs::path good = dir / "RX025_t2.csv";
  std::ofstream(good, std::ios::binary) << kGood;
  const MeasuredTrial m = read_trial_csv(good);
  check_good_channels(m);
  CHECK(m.source == good);
  fs::remove_all(dir);
}
