// The layers of docs/architecture.md, checked on the source tree: a source file includes only
// headers of its own target or of a target below it, and every CMake link line names only such
// targets. A lower layer that includes a higher one (the store including the point runner, say)
// fails here with the file, the line and the include.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// The targets and what each may use (transitively closed), lowest first: docs/architecture.md.
const std::map<std::string, std::set<std::string>> kMayUse = {
    {"records", {}},
    {"config", {}},
    {"correlate", {}},
    {"engine_core", {}},
    {"mesh", {"engine_core"}},
    {"engine", {"mesh", "engine_core"}},
    {"fields", {"engine", "mesh", "engine_core"}},
    {"distributed", {"engine", "mesh", "engine_core"}},
    {"study", {"records", "config", "engine_core"}},
    {"run", {"study", "records", "config", "engine", "mesh", "engine_core"}},
    {"rig_data", {"config", "correlate"}},
    {"rig",
     {"rig_data", "config", "correlate", "run", "study", "records", "engine", "mesh",
      "engine_core"}},
    {"bench_test", {"rig_data", "config", "correlate"}},
    {"db", {"records", "study", "config", "correlate", "engine_core", "rig_data"}},
    {"reports", {"records", "study", "config", "correlate", "engine_core", "db", "rig_data"}},
    {"cli",
     {"records", "config", "correlate", "engine_core", "mesh", "engine", "fields", "distributed",
      "study", "run", "rig_data", "rig", "bench_test", "db", "reports"}},
};

// The target a source path (relative to the repository root) belongs to; empty for files outside
// the layered libraries (tests, benchmarks, scripts).
std::string target_of(const std::string& path) {
  static const std::vector<std::pair<std::string, std::string>> kFolders = {
      {"records/", "records"},
      {"config/", "config"},
      {"correlate/", "correlate"},
      {"engine/core/", "engine_core"},
      {"engine/mesh/", "mesh"},
      {"engine/material/", "mesh"},
      {"engine/distributed/", "distributed"},
      {"engine/", "engine"},
      {"io/fields/", "fields"},
      {"study/", "study"},
      {"run/", "run"},
      {"rig_models/geometry/", "rig"},
      {"rig_models/drive/", "rig"},
      {"rig_models/sim/", "rig"},
      {"rig_models/", "rig_data"},
      {"bench_test/", "bench_test"},
      {"db/", "db"},
      {"reports/", "reports"},
      {"app/", "cli"},
  };
  for (const auto& [folder, target] : kFolders)
    if (path.rfind(folder, 0) == 0) return target;
  return {};
}

fs::path source_root() { return fs::path(CCM_SOURCE_DIR); }

std::vector<std::string> layered_sources() {
  std::vector<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(source_root())) {
    const std::string rel = fs::relative(e.path(), source_root()).generic_string();
    if (rel.rfind("build", 0) == 0 || rel.rfind(".", 0) == 0) continue;
    const std::string ext = e.path().extension().string();
    if ((ext == ".cpp" || ext == ".hpp") && !target_of(rel).empty()) out.push_back(rel);
  }
  return out;
}

bool may_use(const std::string& from, const std::string& to) {
  return from == to || kMayUse.at(from).count(to) > 0;
}

}  // namespace

TEST_CASE("layers: no source includes a header of a higher or sideways layer", "[architecture]") {
  const std::regex include_line(R"re(^\s*#\s*include\s*"([^"]+)")re");
  const std::vector<std::string> sources = layered_sources();
  REQUIRE(sources.size() > 200);  // the walk found the tree
  std::vector<std::string> violations;
  for (const std::string& rel : sources) {
    std::ifstream in(source_root() / rel);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
      std::smatch m;
      if (!std::regex_search(line, m, include_line)) continue;
      const std::string to = target_of(m[1].str());
      if (to.empty()) continue;  // a generated or third-party header
      const std::string from = target_of(rel);
      if (!may_use(from, to))
        violations.push_back(rel + ":" + std::to_string(n) + ": " + from + " includes " +
                             m[1].str() + " (" + to + ")");
    }
  }
  INFO(violations.size() << " violations");
  for (const std::string& v : violations) UNSCOPED_INFO(v);
  CHECK(violations.empty());
}

TEST_CASE("layers: every CMake link line names only the targets its layer may use",
          "[architecture]") {
  // target_link_libraries(ccm_<name> ... ccm::<dep> ... ccm_<dep> ...)
  const std::regex link_call(R"re(target_link_libraries\(\s*ccm_(\w+)([^)]*)\))re");
  const std::regex dep(R"re(\bccm(?:::|_)(\w+))re");
  int checked = 0;
  std::vector<std::string> violations;
  for (const auto& e : fs::recursive_directory_iterator(source_root())) {
    const std::string rel = fs::relative(e.path(), source_root()).generic_string();
    if (e.path().filename() != "CMakeLists.txt" || rel.rfind("build", 0) == 0 ||
        rel.rfind("tests/", 0) == 0 || rel.rfind("bench/", 0) == 0)
      continue;
    std::ifstream in(e.path());
    std::ostringstream all;  // (istreambuf_iterator here draws a GCC 12 -Wnull-dereference)
    all << in.rdbuf();
    const std::string text = all.str();
    for (std::sregex_iterator it(text.begin(), text.end(), link_call), end; it != end; ++it) {
      const std::string from = (*it)[1].str();
      if (!kMayUse.count(from)) continue;  // the executable, ccm_version_info
      ++checked;
      const std::string deps = (*it)[2].str();
      for (std::sregex_iterator d(deps.begin(), deps.end(), dep); d != end; ++d) {
        const std::string to = (*d)[1].str();
        if (to == "warnings") continue;
        if (!kMayUse.count(to) || !may_use(from, to))
          violations.push_back(rel + ": ccm_" + from + " links " + (*d)[0].str());
      }
    }
  }
  CHECK(checked >= 15);  // every library target's link line was read
  for (const std::string& v : violations) UNSCOPED_INFO(v);
  CHECK(violations.empty());
}

namespace {

// The folders inside engine/, lowest first (docs/architecture.md, "Inside the engine"): a file of
// one folder includes headers of its own folder or of folders below it, never above.
const std::vector<std::string> kEngineLayers = {"core",    "threads", "material", "mesh",
                                                "element", "monitor", "bc",       "observe",
                                                "body",    "contact", "solver",   "distributed"};

// The rank of an engine path's folder ("engine/contact/dcr/x.hpp": contact), or -1.
int engine_layer(const std::string& path) {
  if (path.rfind("engine/", 0) != 0) return -1;
  const std::string rest = path.substr(7);
  const std::string folder = rest.substr(0, rest.find('/'));
  for (size_t k = 0; k < kEngineLayers.size(); ++k)
    if (kEngineLayers[k] == folder) return static_cast<int>(k);
  return -2;  // a folder the list does not know: a new one must be placed in it
}

}  // namespace

TEST_CASE("layers: inside the engine, no folder includes a header of a folder above it",
          "[architecture]") {
  const std::regex include_line(R"re(^\s*#\s*include\s*"(engine/[^"]+)")re");
  std::vector<std::string> violations;
  int files = 0;
  for (const std::string& rel : layered_sources()) {
    const int from = engine_layer(rel);
    if (from == -1) continue;
    ++files;
    if (from == -2) violations.push_back(rel + ": its folder is not in kEngineLayers");
    std::ifstream in(source_root() / rel);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
      std::smatch m;
      if (!std::regex_search(line, m, include_line)) continue;
      const int to = engine_layer(m[1].str());
      if (to > from)
        violations.push_back(rel + ":" + std::to_string(n) + ": includes " + m[1].str() + " (" +
                             kEngineLayers[static_cast<size_t>(to)] + " is above " +
                             kEngineLayers[static_cast<size_t>(from)] + ")");
    }
  }
  CHECK(files > 100);  // the walk found the engine
  for (const std::string& v : violations) UNSCOPED_INFO(v);
  CHECK(violations.empty());
}

TEST_CASE("layers: the checker sees a violation", "[architecture]") {
  CHECK(engine_layer("engine/contact/dcr/dcr_contact.hpp") >
        engine_layer("engine/body/rigid_body.hpp"));
  CHECK(engine_layer("engine/solver/model.hpp") > engine_layer("engine/contact/contact_model.hpp"));
  CHECK(engine_layer("engine/newfolder/x.hpp") == -2);
  // The rule itself, on the cases the tree must never contain.
  CHECK_FALSE(may_use("db", "engine"));
  CHECK_FALSE(may_use("reports", "run"));
  CHECK_FALSE(may_use("engine", "study"));
  CHECK_FALSE(may_use("rig_data", "engine"));
  CHECK(target_of("rig_models/sim/rig_run.hpp") == "rig");
  CHECK(target_of("rig_models/compare/case_comparison.hpp") == "rig_data");
  CHECK(target_of("engine/core/state.hpp") == "engine_core");
}
