// A run that ends when its impact has ended ([time] end_after_separation, TimeControl): a ball
// thrown at a clamped block rebounds and flies off. The run with the criterion ends within one
// output interval of the separation the full run records (its DCR `contact.active` column) plus
// the hold; up to that end its histories are the full run's, bit for bit (the criterion changes
// nothing it does not cut), and its energy balance is as good. A ball held down hard lands and
// stays, never separating for the hold: it runs to its guard and says so.
#include <fmt/format.h>

#include <algorithm>
#include <catch2/catch.hpp>

#include "run/scene/scene_file.hpp"
#include "run/scene/scene_run.hpp"

using namespace ccm;

namespace {

// A 1 cm ball 0.5 mm above a clamped 3 cm block, thrown down at 1 m/s (restitution `e`), under
// `gravity`; `hold`: the criterion's hold time, "" for none.
std::string ball_on_block(double e, double gravity, const std::string& hold) {
  return fmt::format(R"([time]
end = 0.03
output_interval = 2e-4
{}
[gravity]
acceleration = [0.0, 0.0, {}]

[[bodies]]
name = "ball"
initial_velocity = [0.0, 0.0, -1.0]
[bodies.material]
E = 1e6
nu = 0.3
rho = 1000.0
[bodies.geometry]
shape = "sphere"
radius = 0.005
mesh_size = 0.0025
[bodies.placement]
translate = [0.015, 0.015, 0.0155]

[[bodies]]
name = "block"
[bodies.material]
E = 1e6
nu = 0.3
rho = 1000.0
[bodies.geometry]
shape = "box"
size = [0.03, 0.03, 0.01]
mesh_size = 0.005

[[fixed]]
body = "block"
plane = {{ point = [0.0, 0.0, 0.0], normal = [0.0, 0.0, 1.0] }}

[contact]
model = "dcr"
surfaces = ["ball", "block"]
restitution = {}
)",
                     hold.empty() ? "" : "end_after_separation = " + hold, gravity, e);
}

struct Ran {
  RunSummary summary;
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
};

Ran run(const std::string& text) {
  const SceneRun scene = assemble_scene_run(parse_scene(text, "ball_on_block.toml"));
  HistoryRecorder history(scene.model.mesh, scene.output);
  Ran r;
  r.summary = run_explicit(scene.model, scene_run_options(scene, &history));
  r.columns = history.columns();
  r.rows = history.rows();
  return r;
}

std::size_t column(const Ran& r, const std::string& name) {
  const auto it = std::find(r.columns.begin(), r.columns.end(), name);
  REQUIRE(it != r.columns.end());
  return static_cast<std::size_t>(it - r.columns.begin());
}

}  // namespace

TEST_CASE(
    "end after separation: a rebounding ball ends one hold after it leaves, nothing else "
    "changed",
    "[end_after_separation]") {
  const double hold = 2e-3, interval = 2e-4;
  const Ran full = run(ball_on_block(1.0, 0.0, ""));
  const Ran cut = run(ball_on_block(1.0, 0.0, fmt::format("{}", hold)));
  REQUIRE(full.summary.verdict == Verdict::completed);
  REQUIRE(cut.summary.verdict == Verdict::completed);
  CHECK(full.summary.ended_by == RunEnd::end_time);
  REQUIRE(cut.summary.ended_by == RunEnd::separated);

  // The separation the full run records: the first sample with no active contact after the last
  // one with some (the ball flies off and never returns).
  const std::size_t t = column(full, "time"), active = column(full, "contact.active");
  std::size_t last_touch = 0;
  for (std::size_t k = 0; k < full.rows.size(); ++k)
    if (full.rows[k][active] > 0.0) last_touch = k;
  REQUIRE(last_touch > 0);
  REQUIRE(last_touch + 1 < full.rows.size());
  const double separated = full.rows[last_touch + 1][t];
  CHECK(cut.summary.end_time >= separated + hold - interval - 1e-12);
  CHECK(cut.summary.end_time <= separated + hold + interval + 1e-12);
  CHECK(cut.summary.end_time < 0.03);
  CHECK(cut.summary.contact_opened_at <= separated);
  CHECK(cut.summary.contact_opened_at > separated - interval);

  // Up to its end the cut run is the full run, every column of every sample.
  REQUIRE(cut.rows.size() < full.rows.size());
  for (std::size_t k = 0; k < cut.rows.size(); ++k) CHECK(cut.rows[k] == full.rows[k]);
  CHECK(cut.summary.energy_balance_error <= full.summary.energy_balance_error);
  CHECK(full.summary.energy_balance_error < 0.01);
}

TEST_CASE("end after separation: a ball that lands and stays runs to its guard and says so",
          "[end_after_separation]") {
  // Under 1000 m/s^2 a rebound at 1 m/s or less flies at most 2 v / g = 2 ms: never the 3 ms hold.
  const Ran r = run(ball_on_block(0.0, -1000.0, "3e-3"));
  REQUIRE(r.summary.verdict == Verdict::completed);
  CHECK(r.summary.touched);
  CHECK(r.summary.ended_by == RunEnd::end_time);
  CHECK(r.summary.end_time == Approx(0.03).epsilon(1e-12));
}

TEST_CASE("end after separation: a hold outside [0, end) is refused with file, line and key",
          "[end_after_separation]") {
  try {
    parse_scene(ball_on_block(1.0, 0.0, "0.05"), "ball_on_block.toml");
    FAIL("no error");
  } catch (const ConfigError& e) {
    CHECK_THAT(e.what(), Catch::Contains("ball_on_block.toml:4: time.end_after_separation: must "
                                         "lie in [0, end = 0.03) (got 0.05)"));
  }
}
