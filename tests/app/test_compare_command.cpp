// `ccm compare` end to end (docs/compare.md): a soft cube struck by another, the striker made
// rigid. The answer is checked against what it claims: the cost ratio is the ratio of the two
// runs' step-loop CPU seconds written beside them, and each final-state error is eq. 2.37
// recomputed here from the two runs' history files. Asked again, both runs are reused, not run;
// a body or an observable that does not exist is refused before anything runs or is written.
#include <fmt/format.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/app/cli_shell.hpp"
#include "tests/study/grid/grid_fixtures.hpp"
#include "tests/support/scene_fixtures.hpp"

namespace fs = std::filesystem;
using Catch::Contains;

namespace {

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

// One column of a history.csv.
std::vector<double> column(const fs::path& csv, const std::string& name) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  std::stringstream header(line);
  size_t at = 0, k = 0;
  for (std::string c; std::getline(header, c, ','); ++k)
    if (c == name) at = k;
  std::vector<double> out;
  while (std::getline(in, line)) {
    std::stringstream cells(line);
    std::string c;
    for (size_t j = 0; j <= at; ++j) std::getline(cells, c, ',');
    out.push_back(std::stod(c));
  }
  return out;
}

// Eq. 2.37: |c(t_f) - r(t_f)| / max(max |c|, max |r|).
double final_state(const std::vector<double>& c, const std::vector<double>& r) {
  double scale = 0.0;
  for (double v : c) scale = std::max(scale, std::abs(v));
  for (double v : r) scale = std::max(scale, std::abs(v));
  return std::abs(c.back() - r.back()) / scale;
}

}  // namespace

TEST_CASE("ccm compare: errors, cost ratio and answer, checked against the two runs",
          "[compare][cli]") {
  ccm::test::TempDir dir;
  const fs::path scene = dir.write("strike.toml", ccm::test::kStrikeScene);
  const fs::path out = dir.path / "cmp";
  const auto first = ccm::test::run_ccm(
      fmt::format("compare '{}' --rigid striker --out '{}' --quiet", scene.string(), out.string()),
      dir);
  INFO(first.err);
  REQUIRE(first.status == 0);
  CHECK_THAT(first.out, Contains("base.u_max") && Contains("cost ratio") && Contains("answer"));
  const nlohmann::json j = read_json(out / "comparison.json");
  REQUIRE(j["errors"].size() == 3);  // the base's u_mean, u_max, kinetic_energy
  const std::string dh = j["deformable_run"]["hash"], rh = j["rigid_run"]["hash"];
  CHECK(dh != rh);
  const nlohmann::json ds = read_json(out / "runs" / (dh + ".json"));
  const nlohmann::json rs = read_json(out / "runs" / (rh + ".json"));
  CHECK(j["cost_ratio"].get<double>() ==
        Approx(ds["step_cpu_seconds"].get<double>() / rs["step_cpu_seconds"].get<double>())
            .epsilon(1e-12));
  for (const nlohmann::json& e : j["errors"]) {
    const std::string name = e["observable"];
    const double expected = final_state(column(out / "runs" / (dh + ".csv"), name),
                                        column(out / "runs" / (rh + ".csv"), name));
    CHECK(e["final_state"].get<double>() == Approx(expected).epsilon(1e-12));
  }
  // The base was struck: it moved, so the comparison compares something.
  CHECK(column(out / "runs" / (dh + ".csv"), "base.u_max").back() > 0.0);
  // The designer's metrics (IM.1, IM.2) from each run's own columns: the striker's mass times
  // its largest velocity change over an output interval, the base's largest u_max.
  REQUIRE(j["impact"].is_object());
  const double mass = j["study_prediction"]["groups"]["m_I"];
  for (const auto& [side, hash] : {std::pair{"deformable", dh}, std::pair{"rigid", rh}}) {
    const fs::path csv = out / "runs" / (hash + ".csv");
    const auto t = column(csv, "time"), vx = column(csv, "striker.vx"),
               vy = column(csv, "striker.vy"), vz = column(csv, "striker.vz");
    double peak = 0.0;
    for (size_t k = 1; k < t.size(); ++k)
      peak = std::max(peak,
                      mass * std::hypot(vx[k] - vx[k - 1], vy[k] - vy[k - 1], vz[k] - vz[k - 1]) /
                          (t[k] - t[k - 1]));
    INFO(side);
    CHECK(peak > 0.0);
    CHECK(j["impact"][side]["peak_force"].get<double>() == Approx(peak).epsilon(1e-12));
    const auto u = column(csv, "base.u_max");
    CHECK(j["impact"][side]["indentation"].get<double>() == *std::max_element(u.begin(), u.end()));
  }
  CHECK_THAT(first.out, Contains("peak contact force [N]"));

  // Asked again (as JSON): both runs reused, the same numbers.
  const auto again = ccm::test::run_ccm(
      fmt::format("compare '{}' --rigid striker --out '{}' --json", scene.string(), out.string()),
      dir);
  REQUIRE(again.status == 0);
  const nlohmann::json j2 = nlohmann::json::parse(again.out);
  CHECK(j2["deformable_run"]["reused"] == true);
  CHECK(j2["rigid_run"]["reused"] == true);
  CHECK(j2["errors"] == j["errors"]);
}

TEST_CASE("ccm compare: a body or an observable that does not exist is refused, nothing written",
          "[compare][cli]") {
  ccm::test::TempDir dir;
  const fs::path scene = dir.write("strike.toml", ccm::test::kStrikeScene);
  const fs::path out = dir.path / "cmp";
  const auto body = ccm::test::run_ccm(
      fmt::format("compare '{}' --rigid strikr --out '{}'", scene.string(), out.string()), dir);
  CHECK(body.status == 2);
  CHECK_THAT(body.err, Contains("no body named 'strikr'") && Contains("did you mean 'striker'?"));
  const auto observe =
      ccm::test::run_ccm(fmt::format("compare '{}' --rigid striker --observe base.umax --out '{}'",
                                     scene.string(), out.string()),
                         dir);
  CHECK(observe.status == 2);
  CHECK_THAT(observe.err, Contains("--observe base.umax") && Contains("did you mean 'base.u_max'"));
  CHECK(!fs::exists(out));
}

TEST_CASE("ccm compare on a whole impact: both runs end together, after both have separated",
          "[compare][cli]") {
  // The striker rebounds (restitution 1) and flies off; each run may end 1 ms after it separates.
  std::string text = ccm::test::kStrikeScene;
  const std::string end = "end = 2e-3\n";
  text.replace(text.find(end), end.size(), "end = 0.02\nend_after_separation = 1e-3\n");
  text += "restitution = 1.0\n";
  ccm::test::TempDir dir;
  const fs::path scene = dir.write("whole.toml", text);
  const fs::path out = dir.path / "cmp";
  const auto r = ccm::test::run_ccm(
      fmt::format("compare '{}' --rigid striker --out '{}' --quiet", scene.string(), out.string()),
      dir);
  INFO(r.err);
  REQUIRE(r.status == 0);
  const nlohmann::json j = read_json(out / "comparison.json");
  const fs::path d = out / "runs" / (j["deformable_run"]["hash"].get<std::string>() + ".csv");
  const fs::path k = out / "runs" / (j["rigid_run"]["hash"].get<std::string>() + ".csv");
  const std::vector<double> td = column(d, "time"), tk = column(k, "time");
  CHECK(td == tk);  // common sample times
  REQUIRE(!td.empty());
  CHECK(td.back() < 0.02);  // ended by the separation, not by the guard
  // At the end neither contact acts (no impulse in the last samples of the hold); both did.
  const std::vector<double> ad = column(d, "contact.normal_impulse"),
                            ak = column(k, "contact.normal_impulse");
  CHECK(*std::max_element(ad.begin(), ad.end()) > 0.0);  // they touched
  CHECK(*std::max_element(ak.begin(), ak.end()) > 0.0);
  for (std::size_t i = td.size() - 5; i < td.size(); ++i) {
    CHECK(ad[i] == 0.0);
    CHECK(ak[i] == 0.0);
  }
}

// Without --db the prediction comes from the reference store ccm ships (here a tiny whole-impact
// study over two density ratios, put in a data folder): the store is named, the density ratio
// level nearest the scene's is used, and a scene that stops at its end is told that the store
// compares whole impacts. The comparison is recorded in the main job's store, not the reference.
TEST_CASE("ccm compare without --db: the prediction from the reference store", "[compare][cli]") {
  ccm::test::TempDir dir;
  const fs::path grid = dir.write(
      "reference.toml", ccm::test::whole_impact_grid("reference", "density_ratio = [1.0, 7.8]\n"));
  const fs::path data = dir.path / "data";
  fs::create_directories(data / "rig");
  fs::create_directories(data / "reference");
  fs::copy_file(fs::path(CCM_SOURCE_DIR) / "rig_models/cases.toml", data / "rig/cases.toml");
  const fs::path store = data / "reference/whole-impacts.sqlite";
  const auto study = ccm::test::run_ccm(
      fmt::format("study run '{}' --db '{}' --quiet", grid.string(), store.string()), dir);
  INFO(study.err);
  REQUIRE(study.status == 0);
  const fs::path scene = dir.write("strike.toml", ccm::test::kStrikeScene);
  // From the temporary folder: no main job's store there, so nothing is recorded.
  const auto cmp = ccm::test::run_command(
      fmt::format("cd '{}' && CCM_DATA_DIR='{}' '{}' compare '{}' --rigid striker --out cmp --json",
                  dir.path.string(), data.string(), CCM_BINARY, scene.string()),
      dir);
  INFO(cmp.err);
  REQUIRE(cmp.status == 0);
  const nlohmann::json j = nlohmann::json::parse(cmp.out);
  const nlohmann::json& p = j["study_prediction"];
  CHECK(p["db"] == store.string());
  REQUIRE(p.contains("on_grid"));
  CHECK(p["on_grid"]["density_ratio"] == 1.0);  // the striker and the base are both 1000 kg/m^3
  CHECK(p["on_grid"]["whole_impacts"] == true);
  bool told = false;
  for (const auto& o : p["outside_grid"])
    told |= o.get<std::string>().find("the store compares whole impacts") != std::string::npos;
  CHECK(told);
  CHECK(j["store"] == "not recorded: no store at results/default-study.sqlite");
}
