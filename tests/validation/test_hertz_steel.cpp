// Issue 15 item 2 and issue 34 item 2, [validation]: the steel Hertz impact of
// scenes/validation/hertz_steel_*.toml (two R = 10 mm steel spheres at +-5 m/s, DCR with
// restitution 1, graded meshes with a / h = 2.5, 3.5, 5 and 10 at the contact poles), run as a user
// runs it (`ccm run`), against the closed form (tests/support/hertz.hpp;
// docs/contact-persistent.md, "Steel spheres at +-5 m/s"): contact duration, peak force (the force
// output, the upper sphere's momentum rate) and maximum approach of the centres, from history rows
// 10 ns apart. Each error must shrink under refinement; at a / 5 the errors are below the
// CalculiX 2.20 figures of issue 15 (3.7 %, 4.2 %, 3.4 %) with the nodal-pressure tet (measured
// -3.03 %, +3.92 %, -3.05 %; the plain tet's approach, -3.54 %, is not). At +-5 m/s the reference
// is the converged dynamic solution, the Richardson limit of a / 3.5, 5, 10 ("The converged
// solution at +-5 m/s"). The energy balance stays within 0.5 %. About 20 minutes in Release on 2
// cores. The last test runs the a / 5 mesh at a tenth of the speed with the nodal-pressure tet
// (about 5 minutes): within the issue's 2 % there (docs/contact-persistent.md, "Steel spheres at
// +-5 m/s", "the speed").
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "tests/app/cli_shell.hpp"
#include "tests/support/hertz.hpp"
#include "tests/support/richardson.hpp"

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

enum class SteelTet { plain, nodal_pressure };

// The scene hertz_steel_<mesh>.toml, whose spheres approach each other at +-speed; with
// SteelTet::nodal_pressure, a copy of it whose two spheres take `element = "nodal_pressure"`.
SteelErrors run_steel(const std::string& mesh, double speed = 5.0, SteelTet tet = SteelTet::plain) {
  test::TempDir dir;
  std::string scene = fmt::format("{}/scenes/validation/hertz_steel_{}.toml", CCM_SOURCE_DIR, mesh);
  if (tet == SteelTet::nodal_pressure) {
    std::string text = test::file_text(scene);
    for (const std::string name : {"low", "up"}) {
      const std::string header = fmt::format("[[bodies]]\nname = \"{}\"\n", name);
      const auto at = text.find(header);
      REQUIRE(at != std::string::npos);
      text.insert(at + header.size(), "element = \"nodal_pressure\"\n");
    }
    scene = (dir.path / "scene_nodal_pressure.toml").string();
    std::ofstream(scene) << text;
  }
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
  WARN(mesh << (tet == SteelTet::nodal_pressure ? " (nodal-pressure tet)" : "") << ": duration "
            << e.duration << ", peak force " << e.force << ", approach " << e.approach
            << ", energy balance " << e.energy);
  return e;
}

// run_steel at +-5 m/s, once per mesh in a process: the test cases below share the meshes.
const SteelErrors& steel_at_5(const std::string& mesh) {
  static std::map<std::string, SteelErrors> done;
  const auto it = done.find(mesh);
  return it != done.end() ? it->second : done.emplace(mesh, run_steel(mesh)).first->second;
}

}  // namespace

TEST_CASE(
    "Steel Hertz impact on graded meshes converges, past CalculiX with the nodal-pressure tet",
    "[validation][hertz]") {
  const SteelErrors& coarse = steel_at_5("h320");
  const SteelErrors& middle = steel_at_5("h230");
  const SteelErrors& fine = steel_at_5("h160");
  for (const SteelErrors& e : {coarse, middle, fine}) CHECK(e.energy < 0.005);
  CHECK(std::abs(middle.duration) < std::abs(coarse.duration));
  CHECK(std::abs(fine.duration) < std::abs(middle.duration));
  CHECK(std::abs(middle.force) < std::abs(coarse.force));
  CHECK(std::abs(fine.force) < std::abs(middle.force));
  CHECK(std::abs(middle.approach) < std::abs(coarse.approach));
  CHECK(std::abs(fine.approach) < std::abs(middle.approach));
  // The plain tet at a / 5 is past CalculiX in duration and peak force, not in approach
  // (-3.54 % against 3.4 %); the nodal-pressure tet is past it in all three.
  CHECK(std::abs(fine.duration) < 0.037);
  CHECK(std::abs(fine.force) < 0.042);
  const SteelErrors fine_np = run_steel("h160", 5.0, SteelTet::nodal_pressure);
  CHECK(fine_np.energy < 0.005);
  CHECK(std::abs(fine_np.duration) < 0.037);
  CHECK(std::abs(fine_np.force) < 0.042);
  CHECK(std::abs(fine_np.approach) < 0.034);
}

// Issue 34 item 2. At +-5 m/s the quasi-static closed form leaves out the impact's elastic waves,
// so the reference is the converged dynamic solution: the Richardson limit
// (tests/support/richardson.hpp) of the contact zone refined to a / 3.5, a / 5 and a / 10 (h230,
// h160, h080). Their far field (1.2 mm, growing over 8 mm) is resolved: refined to 0.8 mm it
// moved the a / 5 errors by 0.2 % (docs/contact-persistent.md). Duration and approach must show
// an observed order in [0.5, 3] (a first-order element's contact converges at about 1-2; outside
// that range the meshes are not yet asymptotic and the limit means nothing). The peak force has
// no limit: the peak of the interval means rides the spheres' ringing. Then the issue's
// fast-graded mesh (hertz_steel_fast_h150.toml: 150 um within 1 mm, 1.2 mm at 8 mm) with the
// nodal-pressure tet must read duration and approach within CalculiX's figures of the closed form
// and within 1.5 % of the converged solution.
TEST_CASE(
    "Steel Hertz impact at +-5 m/s: the converged solution by Richardson extrapolation, and "
    "the fast-graded mesh against it",
    "[validation][hertz]") {
  const SteelErrors& h230 = steel_at_5("h230");
  const SteelErrors& h160 = steel_at_5("h160");
  const SteelErrors& h080 = steel_at_5("h080");
  CHECK(h080.energy < 0.005);
  // The ratios to the closed form, 1 + error, on the contact zone's sizes a / h = 3.5, 5, 10.
  const auto limit_of = [&](double SteelErrors::*measure, const char* name) {
    const auto r = test::richardson(0.23, 1.0 + h230.*measure, 0.16, 1.0 + h160.*measure, 0.08,
                                    1.0 + h080.*measure);
    if (r) WARN(name << ": observed order " << r->order << ", limit " << r->limit - 1.0);
    REQUIRE(r.has_value());
    CHECK(r->order > 0.5);
    CHECK(r->order < 3.0);
    return r->limit;
  };
  const double duration = limit_of(&SteelErrors::duration, "duration");
  const double approach = limit_of(&SteelErrors::approach, "approach");
  const SteelErrors fast = run_steel("fast_h150", 5.0, SteelTet::nodal_pressure);
  CHECK(fast.energy < 0.005);
  CHECK(std::abs(fast.duration) < 0.037);
  CHECK(std::abs(fast.approach) < 0.034);
  CHECK(std::abs((1.0 + fast.duration) / duration - 1.0) < 0.015);
  CHECK(std::abs((1.0 + fast.approach) / approach - 1.0) < 0.015);
}

// At +-0.5 m/s (v / c0 = 1e-4) on the same a / h = 5 with the nodal-pressure tet, all three
// measures are within the 2 % of the closed form (measured -1.70 %, +1.87 %, -1.74 %); at
// +-5 m/s the same mesh and element read -3.03 %, +3.92 %, -3.05 % (docs/contact-persistent.md).
TEST_CASE("Steel Hertz impact at a tenth of the speed is within 2 % at a / 5",
          "[validation][hertz]") {
  const SteelErrors slow = run_steel("slow_h064", 0.5);
  CHECK(slow.energy < 0.005);
  CHECK(std::abs(slow.duration) < 0.02);
  CHECK(std::abs(slow.force) < 0.02);
  CHECK(std::abs(slow.approach) < 0.02);
}
