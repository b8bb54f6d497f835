// Issue 15 item 2, [validation]: the steel Hertz impact of scenes/validation/hertz_steel_h*.toml
// (two R = 10 mm steel spheres at +-5 m/s, DCR with restitution 1, graded meshes with a / h =
// 2.5, 3.5 and 5 at the contact poles), run as a user runs it (`ccm run`), against the closed
// form (tests/support/hertz.hpp; docs/contact-persistent.md, "Steel spheres at +-5 m/s"):
// contact duration, peak force (the force output, the upper sphere's momentum rate) and maximum
// approach of the centres. Each error must shrink under refinement, and on the finest mesh each
// must be below the CalculiX 2.20 figure of issue 15 (3.7 %, 4.2 %, 3.4 %): measured -3.1 %,
// +3.9 %, -2.8 % (docs/evidence.md). The energy balance stays within 0.5 % (measured 0.1-0.4 %).
// About 10 minutes in Release. The second test runs the a / 5 mesh at a tenth of the speed with
// the nodal-pressure tet (about 5 minutes): within the 2 % there
// (docs/contact-persistent.md, "Steel spheres at +-5 m/s", the bullet "the speed").
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "tests/app/cli_shell.hpp"
#include "tests/support/hertz.hpp"

using namespace ccm;

namespace {

using Columns = std::map<std::string, std::vector<double>>;

Columns read_history(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  for (std::stringstream header(line); std::getline(header, line, ',');) names.push_back(line);
  Columns c;
  while (std::getline(in, line)) {
    std::stringstream row(line);
    for (const std::string& name : names) {
      std::string cell;
      std::getline(row, cell, ',');
      c[name].push_back(std::stod(cell));
    }
  }
  return c;
}

struct SteelErrors {
  double duration, force, approach, energy;
};

// The scene hertz_steel_<mesh>.toml, whose spheres approach each other at +-speed.
SteelErrors run_steel(const std::string& mesh, double speed = 5.0) {
  test::TempDir dir;
  const std::string scene =
      fmt::format("{}/scenes/validation/hertz_steel_{}.toml", CCM_SOURCE_DIR, mesh);
  const test::CommandOutput run =
      test::run_ccm(fmt::format("run '{}' --out '{}'", scene, (dir.path / "out").string()), dir);
  REQUIRE(run.status == 0);
  const Columns h = read_history(dir.path / "out" / "history.csv");
  test::HertzCase c;
  c.E = 210e9;
  c.nu = 0.3;
  c.rho = 7850.0;
  c.v = 2.0 * speed;  // closing speed
  const double mass = 2.0 * h.at("low.kinetic_energy")[0] / (speed * speed);
  const test::HertzPrediction p = test::hertz_prediction(c, mass);
  const auto& t = h.at("time");
  const auto& F = h.at("contact.low.up.force_axis");
  double f_max = 0.0;
  for (double f : F) f_max = std::max(f_max, std::abs(f));
  // Each row's force is the mean over the interval that ends at it; the approach counts from the
  // end of the last interval without contact before the first with it.
  double duration = 0.0, closing_at_touch = 0.0, approach = 0.0;
  bool touched = false;
  for (size_t i = 1; i < t.size(); ++i) {
    const double closing = h.at("low_centre.uz")[i] - h.at("up_centre.uz")[i];
    if (std::abs(F[i]) > 1e-9 * f_max) {
      if (!touched) closing_at_touch = h.at("low_centre.uz")[i - 1] - h.at("up_centre.uz")[i - 1];
      touched = true;
      duration += t[i] - t[i - 1];
    }
    if (touched) approach = std::max(approach, closing - closing_at_touch);
  }
  const std::string summary = test::file_text(dir.path / "out" / "summary.toml");
  const auto at = summary.find("energy_balance_error = ");
  REQUIRE(at != std::string::npos);
  const SteelErrors e{
      duration / p.duration - 1.0, f_max / p.force_max - 1.0, approach / p.delta_max - 1.0,
      std::stod(summary.substr(at + std::string("energy_balance_error = ").size()))};
  WARN(mesh << ": duration " << e.duration << ", peak force " << e.force << ", approach "
            << e.approach << ", energy balance " << e.energy);
  return e;
}

}  // namespace

TEST_CASE("Steel Hertz impact on graded meshes converges past CalculiX", "[validation][hertz]") {
  const SteelErrors coarse = run_steel("h320");
  const SteelErrors middle = run_steel("h230");
  const SteelErrors fine = run_steel("h160");
  for (const SteelErrors& e : {coarse, middle, fine}) CHECK(e.energy < 0.005);
  CHECK(std::abs(middle.duration) < std::abs(coarse.duration));
  CHECK(std::abs(fine.duration) < std::abs(middle.duration));
  CHECK(std::abs(middle.force) < std::abs(coarse.force));
  CHECK(std::abs(fine.force) < std::abs(middle.force));
  CHECK(std::abs(middle.approach) < std::abs(coarse.approach));
  CHECK(std::abs(fine.approach) < std::abs(middle.approach));
  CHECK(std::abs(fine.duration) < 0.037);
  CHECK(std::abs(fine.force) < 0.042);
  CHECK(std::abs(fine.approach) < 0.034);
}

// At +-0.5 m/s (v / c0 = 1e-4) on the same a / h = 5 with the nodal-pressure tet, all three
// measures are within the 2 % of the closed form (measured -1.41 %, +1.83 %, -1.30 %); at
// +-5 m/s the same mesh and element read -2.61 %, +3.79 %, -2.35 % (docs/contact-persistent.md).
TEST_CASE("Steel Hertz impact at a tenth of the speed is within 2 % at a / 5",
          "[validation][hertz]") {
  const SteelErrors slow = run_steel("slow_h064", 0.5);
  CHECK(slow.energy < 0.005);
  CHECK(std::abs(slow.duration) < 0.02);
  CHECK(std::abs(slow.force) < 0.02);
  CHECK(std::abs(slow.approach) < 0.02);
}
