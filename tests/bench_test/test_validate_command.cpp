// `ccm validate` end to end on generated bench tests (bench_trial_generator.hpp): a scene's own
// run, recorded as three trials on offset clocks, in mm/s and g, with noise and drift. The clocks
// are recovered within one sample, the scene that made the data rates "excellent" and a striker
// 20 % slower or faster rates lower; bad data is refused before any run.
#include <fmt/format.h>

#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "correlate/cfc_filter.hpp"
#include "db/store/study_store.hpp"
#include "db/store/validation_store.hpp"
#include "tests/app/cli_shell.hpp"
#include "tests/bench_test/bench_trial_generator.hpp"

namespace fs = std::filesystem;
using Catch::Contains;

namespace {

// A stiff striker dropped at `speed` on a soft block fixed at its bottom; the striker's velocity
// every 20 us.
std::string strike_scene(double speed) {
  return fmt::format(R"([time]
end = 8e-3
output_interval = 2e-5

[[bodies]]
name = "base"
[bodies.material]
E = 1e5
nu = 0.3
rho = 1000.0
[bodies.geometry]
shape = "box"
size = [0.01, 0.01, 0.01]
mesh_size = 0.0025

[[bodies]]
name = "striker"
initial_velocity = [0.0, 0.0, {}]
[bodies.material]
E = 1e7
nu = 0.3
rho = 1000.0
[bodies.geometry]
shape = "box"
size = [0.006, 0.006, 0.004]
mesh_size = 0.003
[bodies.placement]
translate = [0.002, 0.002, 0.011]

[[fixed]]
body = "base"
plane = {{ point = [0, 0, 0], normal = [0, 0, 1] }}

[contact]
model = "dcr"
surfaces = ["base", "striker"]
)",
                     -speed);
}

// One column of a history.csv, against its time column.
ccm::test::Curve history_column(const fs::path& csv, const std::string& name) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  std::stringstream header(line);
  std::size_t at = 0, k = 0;
  for (std::string c; std::getline(header, c, ','); ++k)
    if (c == name) at = k;
  REQUIRE(at > 0);
  ccm::test::Curve out;
  while (std::getline(in, line)) {
    std::stringstream cells(line);
    std::vector<double> row;
    for (std::string c; std::getline(cells, c, ',');) row.push_back(std::stod(c));
    out.t.push_back(row[0]);
    out.value.push_back(row[at]);
  }
  return out;
}

constexpr double kOffsets[] = {0.00123, -0.00201, 0.00337};  // s, the loggers' clocks ahead

// The bench test of the scene run at 1 m/s: three trials and the mapping, in `folder`.
double write_bench_test(const fs::path& folder, const fs::path& history, double threshold_share) {
  fs::create_directories(folder);
  const ccm::test::Curve v = history_column(history, "striker.vz");
  const ccm::test::Curve a = ccm::test::rate_of(v);
  // The trigger at a share of the acceleration's peak as the trials show it: at 10 kHz, CFC 600.
  std::vector<double> logged;
  for (double t = 0.0; t <= 8e-3; t += 1e-4) logged.push_back(ccm::test::curve_at(a, t));
  double filtered_peak = 0.0;
  for (double x : ccm::correlate::cfc_filter(logged, 600, 1e-4))
    filtered_peak = std::max(filtered_peak, std::abs(x));
  const double threshold = threshold_share * filtered_peak;
  const std::vector<ccm::test::LoggedChannel> channels = {
      {"speed_mm_s", v, 1e-3, 0.005, 0.002},                // 0.5 % noise, 0.2 % drift of 1 m/s
      {"accel_g", a, 9.80665, 0.01 * filtered_peak, 0.0}};  // 1 % of the peak
  for (unsigned i = 0; i < 3; ++i)
    ccm::test::write_trial(folder / fmt::format("drop_t{}.csv", i + 1), {}, channels, kOffsets[i],
                           8e-3, 100 + i);
  std::ofstream(folder / "bench.toml") << fmt::format(R"([trials]
files = "drop_t*.csv"
time_column = "time_ms"
time_unit = "ms"

[align]
channel = "accel"
threshold = {}

[[channels]]
name = "speed"
column = "speed_mm_s"
unit = "mm/s"
observable = "striker.v"
axis = [0, 0, 1]
filter = "CFC600"

[[channels]]
name = "accel"
column = "accel_g"
unit = "g"
observable = "striker.a"
axis = [0, 0, 1]
filter = "CFC600"
)",
                                                      threshold);
  return threshold;
}

nlohmann::json validate_json(const fs::path& scene, const fs::path& data, ccm::test::TempDir& dir) {
  const auto r = ccm::test::run_ccm(
      fmt::format("validate '{}' --data '{}' --out '{}' --json --quiet", scene.string(),
                  data.string(), (dir.path / ("out-" + scene.stem().string())).string()),
      dir);
  INFO(r.err);
  REQUIRE(r.status == 0);
  return nlohmann::json::parse(r.out);
}

double mean_rating(const nlohmann::json& j, const std::string& channel) {
  for (const nlohmann::json& c : j["channels"])
    if (c["channel"] == channel) return c["mean"]["iso18571"]["overall"].get<double>();
  FAIL("no channel " << channel);
  return 0.0;
}

// The strike run at 1 m/s as `truth.toml` and its bench test in <dir>/bench; returns both paths.
std::pair<fs::path, fs::path> truth_and_bench(ccm::test::TempDir& dir) {
  const fs::path truth = dir.write("strike.toml", strike_scene(1.0));
  const auto run = ccm::test::run_ccm(
      fmt::format("run '{}' --out '{}' --quiet", truth.string(), (dir.path / "truth").string()),
      dir);
  REQUIRE(run.status == 0);
  const fs::path data = dir.path / "bench";
  write_bench_test(data, dir.path / "truth" / "history.csv", 0.3);
  return {truth, data};
}

}  // namespace

TEST_CASE("ccm validate: generated trials are aligned, rated excellent, and lower when off",
          "[bench_test][cli]") {
  ccm::test::TempDir dir;
  const auto [truth, data] = truth_and_bench(dir);

  const nlohmann::json j = validate_json(truth, data, dir);
  REQUIRE(j["clock_shifts"].size() == 3);
  for (int i = 0; i < 3; ++i)  // within one 10 kHz sample
    CHECK(j["clock_shifts"][i].get<double>() == Approx(-kOffsets[i]).margin(1e-4));
  for (const nlohmann::json& c : j["channels"]) {
    INFO(c["channel"]);
    CHECK(c["mean"]["iso18571"]["grade"] == "excellent");
    for (const nlohmann::json& t : c["trials"]) CHECK(t["iso18571"]["overall"].get<double>() > 0.9);
  }
  // The output folder: the rating table and each channel's figure and curves.
  const fs::path out = dir.path / ("out-" + truth.stem().string());
  for (const char* file : {"validation.json", "history.csv", "ratings.csv", "speed.csv",
                           "speed.svg", "accel.csv", "accel.svg"})
    CHECK(fs::exists(out / file));
  CHECK_THAT(ccm::test::file_text(out / "ratings.csv"), Contains("drop_t2.csv"));
  CHECK_THAT(ccm::test::file_text(out / "accel.svg"), Contains("<svg"));
  // Recorded in a store (the report's section draws it: tests/db/test_validation_store.cpp).
  const fs::path store = dir.path / "s.sqlite";
  { ccm::db::StudyStore create(store); }
  const auto recorded = ccm::test::run_ccm(
      fmt::format("validate '{}' --data '{}' --out '{}' --db '{}' --quiet", truth.string(),
                  data.string(), (dir.path / "rec").string(), store.string()),
      dir);
  REQUIRE(recorded.status == 0);
  CHECK_THAT(recorded.out, Contains("(validation 1; `ccm report` shows it)"));
  {
    ccm::db::StudyStore read(store, ccm::db::Access::read_only);
    const auto rows = ccm::db::load_validations(read.connection());
    REQUIRE(rows.size() == 1);
    CHECK(rows[0].scores.size() == 8);  // 2 channels x (3 trials + their mean)
    CHECK(rows[0].curves.size() == 2);
  }
  for (double speed : {0.8, 1.2}) {
    INFO("striker at " << speed << " m/s");
    const fs::path off = dir.write(fmt::format("strike_{}.toml", speed), strike_scene(speed));
    const nlohmann::json o = validate_json(off, data, dir);
    CHECK(mean_rating(o, "speed") < mean_rating(j, "speed") - 0.05);
    CHECK(mean_rating(o, "accel") < mean_rating(j, "accel") - 0.05);
  }
}

TEST_CASE("ccm validate: a run whose curves cannot be scored says why and exits 3",
          "[bench_test][cli]") {
  ccm::test::TempDir dir;
  const auto [truth, data] = truth_and_bench(dir);
  // At 0.05 m/s the striker never reaches the block in 8 ms: no acceleration, no trigger.
  const fs::path slow = dir.write("slow.toml", strike_scene(0.05));
  const fs::path out = dir.path / "slow-out";
  const auto r = ccm::test::run_ccm(fmt::format("validate '{}' --data '{}' --out '{}' --quiet",
                                                slow.string(), data.string(), out.string()),
                                    dir);
  CHECK(r.status == 3);
  CHECK_THAT(r.err, Contains("cannot be scored against the trials: the simulated 'accel' never "
                             "reaches the trigger threshold"));
  CHECK(fs::exists(out / "history.csv"));
  CHECK_FALSE(fs::exists(out / "validation.json"));
}

TEST_CASE("ccm validate: bad data and names that name nothing are refused before any run",
          "[bench_test][cli]") {
  ccm::test::TempDir dir;
  const auto paths = truth_and_bench(dir);  // (clang 14 cannot capture a structured binding)
  const fs::path scene = paths.first, data = paths.second;
  auto refused = [&](const std::string& expected) {
    const fs::path out = dir.path / "never";
    const auto r = ccm::test::run_ccm(fmt::format("validate '{}' --data '{}' --out '{}' --quiet",
                                                  scene.string(), data.string(), out.string()),
                                      dir);
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Contains(expected));
    CHECK_FALSE(fs::exists(out));
  };
  const std::string mapping = ccm::test::file_text(data / "bench.toml");
  auto edit = [&](const std::string& from, const std::string& to) {
    std::string m = mapping;
    m.replace(m.find(from), from.size(), to);
    std::ofstream(data / "bench.toml") << m;
  };
  edit("observable = \"striker.a\"", "observable = \"striker.acc\"");
  refused("bench.toml:22: channels.accel.observable: 'striker.acc' names no output");
  edit("unit = \"g\"", "unit = \"gee\"");
  refused("channels[1].unit: must be one of");
  edit("threshold = ", "threshold = 1e9 #");
  refused("align.threshold: drop_t1.csv: channel 'accel' never reaches 1e+09");
  std::ofstream(data / "bench.toml") << mapping;
  // A fit that names no number of the scene, or no range, is refused before any run.
  for (const auto& [fit, expected] : std::vector<std::pair<std::string, std::string>>{
           {"bodies.striker.initial_velocty=0.6:1.4", "--fit bodies.striker.initial_velocty:"},
           {"bodies.striker.initial_velocity=1.4:0.6", "the upper bound 0.6 must exceed the lower"},
           {"bodies.striker.initial_velocity=fast", "the form is PATH=LO:HI"}}) {
    INFO(fit);
    const fs::path out = dir.path / "never";
    const auto r = ccm::test::run_ccm(fmt::format("validate '{}' --data '{}' --out '{}' --quiet "
                                                  "--fit '{}'",
                                                  scene.string(), data.string(), out.string(), fit),
                                      dir);
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Contains(expected));
    CHECK_FALSE(fs::exists(out));
  }
  std::string trial = ccm::test::file_text(data / "drop_t2.csv");
  const std::size_t third_row = trial.find('\n', trial.find('\n', trial.find('\n') + 1) + 1);
  trial.insert(third_row + 1, "0.1,NaN,3\n");
  std::ofstream(data / "drop_t2.csv") << trial;
  refused("drop_t2.csv:4: ");
}

TEST_CASE("ccm validate --fit: the striker's speed recovered from its own trials",
          "[bench_test][cli][heavy]") {
  ccm::test::TempDir dir;
  const auto [truth, data] = truth_and_bench(dir);
  // Started from 0.87 m/s, fitted on trials 1 and 2, trial 3 left out.
  const fs::path start = dir.write("strike_start.toml", strike_scene(0.87));
  const auto r =
      ccm::test::run_ccm(fmt::format("validate '{}' --data '{}' --out '{}' --json --quiet --fit "
                                     "bodies.striker.initial_velocity=0.6:1.4",
                                     start.string(), data.string(), (dir.path / "fit").string()),
                         dir);
  INFO(r.err);
  REQUIRE(r.status == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const nlohmann::json& p = j["fit"]["parameters"][0];
  const double best = p["best"].get<double>();
  REQUIRE(p["half_width"].is_number());
  const double half_width = p["half_width"].get<double>();
  // Within the fit's own sensitivity (where the objective rises 5 %) and within 3 % of the truth.
  CHECK(std::abs(best - 1.0) <= half_width);
  CHECK(std::abs(best - 1.0) <= 0.03);
  CHECK_FALSE(p["on_lower_bound"].get<bool>());
  CHECK_FALSE(p["on_upper_bound"].get<bool>());
  CHECK(j["fit"]["left_out"] == nlohmann::json::array({"drop_t3.csv"}));
  // The left-out trial, scored with the fitted speed, rates within 0.05 of its rating with the
  // true speed, on both channels.
  const nlohmann::json at_truth = validate_json(truth, data, dir);
  for (std::size_t k = 0; k < 2; ++k) {
    const nlohmann::json& c = j["channels"][k];
    INFO(c["channel"]);
    CHECK(c["trials"][2]["left_out"] == true);
    const double fitted = c["trials"][2]["iso18571"]["overall"].get<double>();
    const double ideal = at_truth["channels"][k]["trials"][2]["iso18571"]["overall"].get<double>();
    CHECK(fitted == Approx(ideal).margin(0.05));
  }
  CHECK(fs::exists(dir.path / "fit" / "fitted.toml"));
}

TEST_CASE("ccm validate --fit --cross-validate: each trial left out in turn",
          "[bench_test][cli][heavy]") {
  ccm::test::TempDir dir;
  const auto [truth, data] = truth_and_bench(dir);
  const fs::path start = dir.write("strike_start.toml", strike_scene(0.87));
  const std::string fit = "--fit bodies.striker.initial_velocity=0.6:1.4";
  const auto r = ccm::test::run_ccm(
      fmt::format("validate '{}' --data '{}' --out '{}' --json --quiet {} --cross-validate",
                  start.string(), data.string(), (dir.path / "cv").string(), fit),
      dir);
  INFO(r.err);
  REQUIRE(r.status == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const nlohmann::json& folds = j["fit"]["cross_validation"];
  REQUIRE(folds.size() == 3);
  for (std::size_t i = 0; i < 3; ++i) {
    INFO("fold " << i);
    CHECK(folds[i]["left_out"] == fmt::format("drop_t{}.csv", i + 1));
    // Fitted on two trials, within 3 % of the truth (the single split's tolerance above), and
    // the trial it did not see rated better than "good" on both channels.
    CHECK(folds[i]["fitted"]["bodies.striker.initial_velocity"].get<double>() ==
          Approx(1.0).margin(0.03));
    for (const char* channel : {"speed", "accel"})
      CHECK(folds[i]["left_out_rating"][channel].get<double>() > 0.9);
  }
  CHECK(j["fit"]["fitted_to"].size() == 3);  // the final fit on every trial
  const auto refused = ccm::test::run_ccm(
      fmt::format("validate '{}' --data '{}' --out '{}' --quiet {} --cross-validate "
                  "--fit-trials 1,2",
                  start.string(), data.string(), (dir.path / "never").string(), fit),
      dir);
  CHECK(refused.status == 2);
  CHECK_THAT(refused.err, Contains("--cross-validate leaves each trial out in turn"));
}
