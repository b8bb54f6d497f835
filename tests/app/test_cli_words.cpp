// The command line's conventions that need no simulation: a word that is no command is named
// with the nearest command, and every command's --help lists its exit codes.
#include <catch2/catch.hpp>
#include <set>
#include <sstream>

#include "tests/app/cli_shell.hpp"

namespace ccm {
namespace {

// The subcommand names in a CLI11 help text: the lines under "Subcommands:".
std::vector<std::string> listed_subcommands(const std::string& help) {
  std::vector<std::string> names;
  std::istringstream lines(help);
  std::string line;
  bool in_list = false;
  while (std::getline(lines, line)) {
    if (line == "Subcommands:") {
      in_list = true;
      continue;
    }
    if (!in_list) continue;
    if (line.size() < 3 || line.rfind("  ", 0) != 0) break;
    std::istringstream words(line);
    std::string name;
    words >> name;
    names.push_back(name);
  }
  return names;
}

}  // namespace

TEST_CASE("ccm with a word that is no command names it and suggests the nearest", "[cli]") {
  test::TempDir dir;
  struct Case {
    std::string args, named, suggestion;
  };
  for (const Case& c : {Case{"stduy run grid.toml --db x.sqlite", "'stduy'", "'study'"},
                        Case{"study sttus --db x.sqlite", "'study sttus'", "'study status'"},
                        Case{"rig lst", "'rig lst'", "'rig list'"},
                        Case{"reprot --db x --out y", "'reprot'", "'report'"}}) {
    const auto r = test::run_ccm(c.args, dir);
    INFO(c.args << "\n" << r.err);
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains("unknown command " + c.named));
    CHECK_THAT(r.err, Catch::Contains("did you mean " + c.suggestion));
    CHECK(r.out.empty());
  }
  // Nothing near: no suggestion, the commands listed.
  const auto r = test::run_ccm("frobnicate", dir);
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains("unknown command 'frobnicate'"));
  CHECK_THAT(r.err, !Catch::Contains("did you mean"));
  CHECK_THAT(r.err,
             Catch::Contains(
                 "the commands of 'ccm' are: run, compare, validate, study, recommend, report"));
  // Nothing is created by a refused command line.
  CHECK_FALSE(std::filesystem::exists("x.sqlite"));
}

TEST_CASE("every command's --help lists its exit codes", "[cli]") {
  test::TempDir dir;
  // Walk the tree of subcommands from `ccm --help`, so that a command added later is checked.
  std::vector<std::string> pending = {""}, checked;
  while (!pending.empty()) {
    const std::string command = pending.back();
    pending.pop_back();
    const auto r = test::run_ccm(command + " --help", dir);
    INFO("ccm " << command << " --help\n" << r.out << r.err);
    CHECK(r.status == 0);
    CHECK_THAT(r.out, Catch::Contains("Exit codes: 0 "));
    CHECK_THAT(r.out, Catch::Contains(" 2 bad input"));
    checked.push_back(command);
    for (const std::string& sub : listed_subcommands(r.out))
      pending.push_back(command.empty() ? sub : command + " " + sub);
  }
  // The tree was walked: the groups and their leaves (others may join).
  const std::set<std::string> seen(checked.begin(), checked.end());
  for (const char* c : {"run", "study", "study run", "study status", "study scene", "recommend",
                        "report", "rig", "rig list", "rig run", "rig calibrate"}) {
    INFO(c);
    CHECK(seen.count(c) == 1);
  }
}

}  // namespace ccm
