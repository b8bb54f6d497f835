// Running the ccm executable (or any command) from a test: exit code, standard output and
// standard error, each captured into a file of the test's temporary folder.
#pragma once

#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/support/temp_dir.hpp"

namespace ccm::test {

struct CommandOutput {
  int status = -1;  // the exit code; -1 when the command did not exit normally
  std::string out, err;
};

inline std::string file_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Runs `command` with /bin/sh; `command` may hold redirections of its own for stdin only.
inline CommandOutput run_command(const std::string& command, const TempDir& dir) {
  const std::filesystem::path out = dir.path / "command-stdout.txt";
  const std::filesystem::path err = dir.path / "command-stderr.txt";
  const int raw =
      std::system((command + " > '" + out.string() + "' 2> '" + err.string() + "'").c_str());
  CommandOutput r;
  r.status = raw != -1 && WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = file_text(out);
  r.err = file_text(err);
  return r;
}

// `ccm ARGS` with the executable under test.
inline CommandOutput run_ccm(const std::string& args, const TempDir& dir) {
  return run_command("'" + std::string(CCM_BINARY) + "' " + args, dir);
}

}  // namespace ccm::test
