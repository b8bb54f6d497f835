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
