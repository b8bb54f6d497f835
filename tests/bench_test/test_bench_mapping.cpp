// The bench test's mapping file (bench_test/bench_mapping.hpp): what it reads and what it
// refuses, each refusal naming the file, the line and the key.
#include <catch2/catch.hpp>
#include <string>

#include "bench_test/bench_mapping.hpp"
#include "bench_test/units.hpp"
#include "config/config_error.hpp"

using ccm::ConfigError;
using ccm::bench::BenchMapping;
using ccm::bench::FilterKind;
using ccm::bench::parse_bench_mapping;

namespace {

const std::string kGood = R"(
[trials]
files = "drop_t*.csv"
time_column = "t_ms"
time_unit = "ms"

[align]
channel = "load"
threshold = 50.0

[[channels]]
name = "load"
column = "F_kN"
unit = "kN"
observable = "ball.contact_force"
axis = [0, 0, 2]
scale = -1
filter = "CFC 180"
deadband = 5.0
window = [0.0, 0.02]

[[channels]]
name = "accel"
column = "a_g"
unit = "g"
observable = "buckle.a"
filter = "low_pass"
cutoff = 64
)";

// The mapping with `from` replaced by `to` (the first occurrence).
std::string with(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

}  // namespace

TEST_CASE("bench mapping: a full mapping is read in SI", "[bench_test]") {
  const BenchMapping m = parse_bench_mapping(kGood, "bench.toml");
  CHECK(m.files_pattern == "drop_t*.csv");
  CHECK(m.time_factor == 1e-3);
  REQUIRE(m.channels.size() == 2);
  const auto& load = m.channels[0];
  CHECK(load.si_factor == 1e3);
  CHECK(load.filter.kind == FilterKind::cfc);
  CHECK(load.filter.frequency == 180.0);
  CHECK((*load.axis)[2] == 1.0);  // normalised
  CHECK(load.scale == -1.0);
  CHECK(load.deadband == 5.0);
  CHECK((*load.window)[1] == 0.02);
  CHECK(m.channels[1].si_factor == Approx(9.80665));
  CHECK(m.channels[1].filter.kind == FilterKind::low_pass);
  CHECK(m.channels[1].filter.frequency == 64.0);
  CHECK(*m.align.channel == "load");
  CHECK(m.align.threshold == 50.0);
}

TEST_CASE("bench mapping: every defect is refused naming the file, line and key", "[bench_test]") {
  struct Case {
    std::string from, to, message;
  };
  const Case cases[] = {
      {"unit = \"kN\"", "unit = \"kNm\"", "bench.toml:14: channels[0].unit: must be one of"},
      {"unit = \"kN\"\n", "", "bench.toml:11: channels[0].unit: required key is missing"},
      {"time_unit = \"ms\"", "time_unit = \"mm\"", "trials.time_unit: 'mm' is not a unit of time"},
      {"filter = \"CFC 180\"", "filter = \"Butterworth\"",
       "channels[0].filter: 'Butterworth' is not a filter"},
      {"cutoff = 64", "cutoff = -64", "channels[1].cutoff: -64 Hz must be > 0"},
      {"window = [0.0, 0.02]", "window = [0.02, 0.0]", "channels[0].window: end 0 s must be after"},
      {"axis = [0, 0, 2]", "axis = [0, 0, 0]", "channels[0].axis: must not be zero"},
      {"channel = \"load\"", "channel = \"lod\"", "align.channel: must be one of"},
      {"threshold = 50.0", "threshold = 0.0", "align.threshold: 0 must be > 0"},
      {"name = \"accel\"", "name = \"load\"", "channels[1].name: 'load' names an earlier channel"},
      {"column = \"a_g\"", "column = \"t_ms\"", "channels[1].column: 't_ms' is the time column"},
      {"deadband = 5.0", "deadband = 5.0\nsmoothing = 3", "unknown key 'smoothing'"},
      {"files = \"drop_t*.csv\"", "files = \"../drop_t*.csv\"",
       "trials.files: a file-name pattern"},
      {"threshold = 50.0", "threshold = 50.0\noffsets = [0.0]", "align: names either a trigger"},
  };
  for (const Case& c : cases) {
    INFO(c.to);
    CHECK_THROWS_WITH(parse_bench_mapping(with(kGood, c.from, c.to), "bench.toml"),
                      Catch::Contains(c.message));
    CHECK_THROWS_AS(parse_bench_mapping(with(kGood, c.from, c.to), "bench.toml"), ConfigError);
  }
}

TEST_CASE("bench mapping: events, a window of an event and the deadband's place are read",
          "[bench_test]") {
  const std::string text = with(kGood, "cutoff = 64\n",
                                "cutoff = 64\nwindow = \"impact\"\ndeadband = 2\n"
                                "deadband_first = true\n\n[[events]]\nname = \"impact\"\n"
                                "channel = \"load\"\nthreshold = 100\n");
  const BenchMapping m = parse_bench_mapping(text, "bench.toml");
  REQUIRE(m.events.size() == 1);
  CHECK(m.events[0].channel == "load");
  CHECK(m.events[0].threshold == 100.0);
  CHECK(*m.channels[1].window_event == "impact");
  CHECK_FALSE(m.channels[1].window);
  CHECK(m.channels[1].deadband_first);
  CHECK_FALSE(m.channels[0].deadband_first);
  CHECK(m.event("impact") == &m.events[0]);

  struct Case {
    std::string from, to, message;
  };
  const Case cases[] = {
      {"window = \"impact\"", "window = \"impakt\"", "channels[1].window: must be one of"},
      {"channel = \"load\"\nthreshold = 100", "channel = \"lode\"\nthreshold = 100",
       "events[0].channel: must be one of"},
      {"threshold = 100", "threshold = -1", "events[0].threshold: -1 must be > 0"},
      {"threshold = 100", "threshold = 100\nduration = 3", "unknown key 'duration'"},
      {"deadband_first = true", "deadband_first = 1", "channels[1].deadband_first"},
  };
  for (const Case& c : cases) {
    INFO(c.to);
    CHECK_THROWS_WITH(parse_bench_mapping(with(text, c.from, c.to), "bench.toml"),
                      Catch::Contains(c.message));
  }
  CHECK_THROWS_WITH(
      parse_bench_mapping(with(kGood, "cutoff = 64\n", "cutoff = 64\nwindow = \"x\"\n"),
                          "bench.toml"),
      Catch::Contains("channels[1].window: 'x' names no [[events]] entry"));
}

TEST_CASE("bench mapping: the units convert to SI", "[bench_test]") {
  using ccm::bench::si_factor;
  CHECK(*si_factor("g") == 9.80665);
  CHECK(*si_factor("mm") == 1e-3);
  CHECK(*si_factor("kPa") == 1e3);
  CHECK(*si_factor("psi") == Approx(6894.757).epsilon(1e-6));
  CHECK(*si_factor("lbf") == Approx(4.448222).epsilon(1e-6));
  CHECK(*si_factor("deg") == Approx(3.14159265358979 / 180).epsilon(1e-12));
  CHECK(*si_factor("km/h") == Approx(1 / 3.6).epsilon(1e-12));
  CHECK_FALSE(si_factor("furlong"));
  CHECK(ccm::bench::si_unit("g") == "m/s^2");
  CHECK(ccm::bench::si_unit("psi") == "Pa");
  CHECK(ccm::bench::si_unit("furlong").empty());
}
