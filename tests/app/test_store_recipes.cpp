// The Python recipes of docs/store.md (sqlite3, pandas, h5py), run as written on a store made
// by a tiny study (`ccm study run`, 2 points x 2 models, about a second): each block must run
// and print what the store holds. Needs python3 with pandas and h5py (scripts/install-deps.sh):
// without them the test fails.
#include <fmt/format.h>

#include <catch2/catch.hpp>
#include <regex>

#include "db/store/study_store.hpp"
#include "tests/app/cli_shell.hpp"
#include "tests/study/grid/grid_fixtures.hpp"

namespace ccm {
namespace {

namespace fs = std::filesystem;

// Debian's interpreter, the one python3-pandas and python3-h5py install into (a `python3` found
// first on PATH, e.g. a pyenv shim, may lack them).
constexpr const char* kDebianPython = "/usr/bin/python3";

const std::string kRecipeGrid = R"(title = "recipes"
[axes]
ER = [1.0, 100.0]
RLS = [0.5]
KE = [0.001]
[time]
contact_time = 0.02
end = 0.03
output_interval = 1e-3
)" + std::string(test::kTinyGridBodies);

// The ```python blocks of a Markdown file, in order.
std::vector<std::string> python_blocks(const std::string& markdown) {
  std::vector<std::string> blocks;
  const std::regex fence("```python\n([\\s\\S]*?)```");
  for (auto it = std::sregex_iterator(markdown.begin(), markdown.end(), fence);
       it != std::sregex_iterator(); ++it)
    blocks.push_back((*it)[1].str());
  return blocks;
}

}  // namespace

TEST_CASE("docs/store.md's Python recipes run on a store made by a tiny study", "[store][python]") {
  test::TempDir dir;
  const fs::path grid = dir.write("recipes.toml", kRecipeGrid);
  const fs::path db = dir.path / "study.sqlite";
  const auto study = test::run_ccm(
      fmt::format("study run '{}' --db '{}' --quiet", grid.string(), db.string()), dir);
  INFO(study.err);
  REQUIRE(study.status == 0);

  const auto blocks = python_blocks(test::file_text(fs::path(CCM_SOURCE_DIR) / "docs/store.md"));
  REQUIRE(blocks.size() == 3);
  std::vector<std::string> printed;
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    std::string code = blocks[k];
    const std::string placeholder = "Path(\"study.sqlite\")";
    const auto at = code.find(placeholder);
    REQUIRE(at != std::string::npos);  // every recipe names its store the same way
    code.replace(at, placeholder.size(), fmt::format("Path(\"{}\")", db.string()));
    const fs::path script = dir.write(fmt::format("recipe{}.py", k), code);
    const auto r =
        test::run_command(std::string(kDebianPython) + " '" + script.string() + "'", dir);
    INFO("recipe " << k << ":\n" << code << "\n" << r.err);
    REQUIRE(r.status == 0);
    printed.push_back(r.out);
  }

  // sqlite3: one line per point, both runs completed.
  CHECK_THAT(printed[0],
             Catch::Contains("point 0: ER 1, RLS 0.5, KE 0.001 J: ccm completed, rigid completed"));
  CHECK_THAT(printed[0],
             Catch::Contains("point 1: ER 100, RLS 0.5, KE 0.001 J: ccm completed, rigid "
                             "completed"));
  // pandas: the metrics of both points and the RTR table of the one kinetic energy.
  CHECK_THAT(printed[1], Catch::Contains("point_index"));
  CHECK_THAT(printed[1], Catch::Contains("measured RTR at KE = 0.001 J"));
  // h5py: the histories the store API reads, as sampled (0 ... 30 ms every 1 ms).
  db::StudyStore store(db, db::Access::read_only);
  REQUIRE(store.open_existing_study());
  const auto status = store.status();
  REQUIRE(status.size() == 2);
  const auto ccm_run = store.load_run(status[0].point, study::ImpactModel::ccm);
  const auto rigid_run = store.load_run(status[0].point, study::ImpactModel::rigid);
  REQUIRE(ccm_run.has_value());
  REQUIRE(rigid_run.has_value());
  CHECK_THAT(printed[2], Catch::Contains("31 samples from 0 s to 0.03 s"));
  CHECK_THAT(printed[2], Catch::Contains(fmt::format("final u_max: ccm {:.6g} m, rigid {:.6g} m",
                                                     ccm_run->artifact.u_max.back(),
                                                     rigid_run->artifact.u_max.back())));
}

}  // namespace ccm
