// Reading a bench test's trial files (bench_test/bench_trials.hpp): SI values, and every defect
// of a messy file refused naming the file, the line and the column.
#include <fmt/format.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>

#include "bench_test/bench_mapping.hpp"
#include "bench_test/bench_trials.hpp"
#include "config/config_error.hpp"
#include "config/text_file.hpp"
#include "rig_models/measurement/trial_csv.hpp"

using ccm::bench::BenchMapping;
using ccm::bench::parse_bench_trial;

namespace {

BenchMapping mapping() {
  return ccm::bench::parse_bench_mapping(R"(
[trials]
files = "t*.csv"
time_column = "time_ms"
time_unit = "ms"
[[channels]]
name = "load"
column = "load_kN"
unit = "kN"
observable = "x"
)",
                                         "bench.toml");
}

// A clean file: 12 rows at 0.1 ms, load k kN.
std::string clean() {
  std::string s = "time_ms,load_kN,extra\n";
  for (int k = 0; k < 12; ++k) s += std::to_string(0.1 * k) + "," + std::to_string(k) + ",7\n";
  return s;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

}  // namespace

TEST_CASE("bench trials: a clean file in SI, with CRLF and a BOM", "[bench_test]") {
  std::string crlf;
  for (char c : clean()) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  const auto trial = parse_bench_trial("\xEF\xBB\xBF" + crlf + "\r\n", "t1.csv", mapping());
  REQUIRE(trial.t.size() == 12);
  CHECK(trial.t[3] == Approx(3e-4));
  CHECK(trial.channels.at("load").value[3] == Approx(3000.0));
}

TEST_CASE("bench trials: every defect is refused naming the file, the line and the column",
          "[bench_test]") {
  struct Case {
    std::string from, to, message;
  };
  const Case cases[] = {
      {"load_kN,", "load_kn,",
       "t1.csv:1: load_kN: the mapping names this column; the header lacks it (did you mean "
       "'load_kn'?)"},
      {"time_ms,", "time,", "t1.csv:1: time_ms: the mapping names this column"},
      {"extra", "load_kN", "t1.csv:1: load_kN: the header names this column twice"},
      {"0.300000,3,7", "0.300000,3", "t1.csv:5: 2 cells; the header has 3"},
      {"0.300000,3,7", "0.300000,abc,7", "t1.csv:5: load_kN: non-numeric cell 'abc'"},
      {"0.300000,3,7", "0.300000,nan,7", "t1.csv:5: load_kN: non-finite number"},
      {"0.300000,3,7", "0.100000,3,7", "t1.csv:5: time_ms: time 0.0001 s goes back"},
      {"0.300000,3,7", "0.200000,3,7", "t1.csv:5: time_ms: time 0.0002 s repeats"},
      {"1.100000,11,7", "1000.1,11,7", "t1.csv:13: time_ms: the clock jumps"},
      {"time_ms,load_kN,extra", "time_ms;load_kN;extra", "cells are separated by ';'"},
  };
  for (const Case& c : cases) {
    INFO(c.to);
    CHECK_THROWS_WITH(parse_bench_trial(replaced(clean(), c.from, c.to), "t1.csv", mapping()),
                      Catch::Contains(c.message));
  }
  CHECK_THROWS_WITH(parse_bench_trial("time_ms,load_kN\n0,1\n", "t1.csv", mapping()),
                    Catch::Contains("1 data rows; a trial needs at least 10"));
  CHECK_THROWS_WITH(parse_bench_trial("", "t1.csv", mapping()), Catch::Contains("empty"));
}

TEST_CASE("bench trials: the folder's files in name order, and none refused", "[bench_test]") {
  const auto dir = std::filesystem::temp_directory_path() / "ccm-bench-trials-test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  BenchMapping m = mapping();
  m.file = dir / "bench.toml";
  CHECK_THROWS_WITH(ccm::bench::read_bench_trials(m), Catch::Contains("trials.files: no file in"));
  for (const char* name : {"t2.csv", "t1.csv", "other.csv"}) std::ofstream(dir / name) << clean();
  const auto trials = ccm::bench::read_bench_trials(m);
  REQUIRE(trials.size() == 2);
  CHECK(trials[0].file.filename() == "t1.csv");
  m.align.offsets = {0.0};
  CHECK_THROWS_WITH(ccm::bench::read_bench_trials(m),
                    Catch::Contains("align.offsets: 1 offsets for 2 trials"));
  std::filesystem::remove_all(dir);
}

TEST_CASE(
    "bench trials: a logger's export: preamble, quoted names, units row, semicolons, decimal "
    "commas",
    "[bench_test]") {
  // As a European-locale data logger writes it: two lines of preamble, quoted column names, a
  // row of units under them, semicolons between cells and decimal commas.
  const BenchMapping m = ccm::bench::parse_bench_mapping(R"(
[trials]
files = "*.csv"
time_column = "Time"
time_unit = "ms"
delimiter = ";"
decimal = ","
header_line = 3
skip_after_header = 1
[[channels]]
name = "load"
column = "Force"
unit = "kN"
observable = "x"
)",
                                                         "bench.toml");
  std::string text =
      "Test: buckle drop 3\n# operator; bench 2\n\"Time\";\"Force\";\"Note\"\n"
      "\"ms\";\"kN\";\"-\"\n";
  for (int k = 0; k < 12; ++k) text += fmt::format("{},{};{},5;ok\n", k / 10, k % 10, k);
  const auto trial = parse_bench_trial(text, "t1.csv", m);
  REQUIRE(trial.t.size() == 12);
  CHECK(trial.t[11] == Approx(1.1e-3));
  CHECK(trial.channels.at("load").value[3] == Approx(3500.0));
  // The same file read with the default layout names what to change.
  CHECK_THROWS_WITH(parse_bench_trial(text, "t1.csv", mapping()),
                    Catch::Contains("the header lacks it"));
  BenchMapping wrong_line = m;
  wrong_line.header_line = 40;
  CHECK_THROWS_WITH(parse_bench_trial(text, "t1.csv", wrong_line),
                    Catch::Contains("t1.csv:40: the mapping's header_line 40 is blank or past"));
  BenchMapping commas = m;
  commas.delimiter = ',';
  commas.decimal = '.';
  commas.header_line = 0;
  commas.skip_after_header = 0;
  CHECK_THROWS_WITH(parse_bench_trial("a;b;c\n", "t1.csv", commas),
                    Catch::Contains("cells are separated by ';'; the mapping reads ',' (set "
                                    "delimiter = \";\" in [trials])"));
}

TEST_CASE("bench trials: no time column, the clock from the sample rate", "[bench_test]") {
  const BenchMapping m = ccm::bench::parse_bench_mapping(R"(
[trials]
files = "*.csv"
sample_rate = 20000
[[channels]]
name = "load"
column = "load_kN"
unit = "kN"
observable = "x"
)",
                                                         "bench.toml");
  std::string text = "load_kN\n";
  for (int k = 0; k < 10; ++k) text += fmt::format("{}\n", k);
  const auto trial = parse_bench_trial(text, "t1.csv", m);
  REQUIRE(trial.t.size() == 10);
  CHECK(trial.t[4] == Approx(4 / 20000.0));
  CHECK_THROWS_WITH(ccm::bench::parse_bench_mapping(
                        "[trials]\nfiles = \"*\"\nsample_rate = 1e4\ntime_column = \"t\"\n"
                        "[[channels]]\nname = \"a\"\ncolumn = \"a\"\nunit = \"N\"\n"
                        "observable = \"x\"\n",
                        "bench.toml"),
                    Catch::Contains("names either time_column (with time_unit) or sample_rate"));
  CHECK_THROWS_WITH(ccm::bench::parse_bench_mapping(
                        "[trials]\nfiles = \"*\"\ntime_column = \"t\"\ntime_unit = \"s\"\n"
                        "decimal = \",\"\n[[channels]]\nname = \"a\"\ncolumn = \"a\"\nunit = "
                        "\"N\"\nobservable = \"x\"\n",
                        "bench.toml"),
                    Catch::Contains("trials.decimal: a decimal comma needs another delimiter"));
}

TEST_CASE("bench trials: the rig's own trial files, sparse rows of sensors at their own rates",
          "[bench_test]") {
  // The rig's measured CSV (docs/measurements.md): '#' metadata lines, sensors at 100 and 128 Hz
  // in one file, a row leaving the cells of the sensors that did not sample empty. Read through a
  // mapping, each channel is exactly what the rig's own reader reads.
  const std::filesystem::path file =
      std::filesystem::path(CCM_SOURCE_DIR) / "tests/data/rig-dev/RX025_t1.csv";
  const BenchMapping m = ccm::bench::parse_bench_mapping(R"(
[trials]
files = "RX025_t*.csv"
time_column = "time_s"
time_unit = "s"
comment = "#"
sparse = true
[[channels]]
name = "velocity"
column = "impactor_velocity_mps"
unit = "m/s"
observable = "x"
[[channels]]
name = "angle"
column = "artifact_angle_deg"
unit = "deg"
observable = "x"
[[channels]]
name = "pressure"
column = "pressure_kpa"
unit = "kPa"
observable = "x"
)",
                                                         file.parent_path() / "bench.toml");
  const auto trial = parse_bench_trial(ccm::read_config_text(file), file, m);
  const ccm::rig::MeasuredTrial rig = ccm::rig::read_trial_csv(file);
  const auto same = [](const ccm::rig::TimeSeries& bench, const ccm::rig::TimeSeries& own,
                       double factor) {
    REQUIRE(bench.t.size() == own.t.size());
    for (std::size_t k = 0; k < own.t.size(); ++k) {
      CHECK(bench.t[k] == own.t[k]);
      CHECK(bench.value[k] == Approx(own.value[k] * factor).epsilon(1e-15));
    }
  };
  same(trial.channels.at("velocity"), rig.impactor_velocity_mps, 1.0);
  same(trial.channels.at("angle"), rig.artifact_angle_deg, 3.14159265358979323846 / 180.0);
  same(trial.channels.at("pressure"), rig.pressure_kpa, 1e3);
  // Without `sparse` the empty cells are refused, naming the line and the column.
  BenchMapping dense = m;
  dense.sparse = false;
  CHECK_THROWS_WITH(parse_bench_trial(ccm::read_config_text(file), file, dense),
                    Catch::Contains("non-numeric cell ''"));
}
