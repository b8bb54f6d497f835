// `--threads` and CCM_THREADS (app/run_command.hpp resolve_threads): an explicit count wins, then
// the environment, then the automatic count; a bad value is refused before any work, and
// `ccm run --threads -1` exits 2 naming the option.
#include <stdlib.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "app/run_command.hpp"

using namespace ccm;

namespace {

// Sets CCM_THREADS for the scope (unset when value is null) and restores the previous value.
class ThreadsVariable {
 public:
  explicit ThreadsVariable(const char* value) {
    if (const char* old = std::getenv("CCM_THREADS")) saved_ = old;
    if (value)
      setenv("CCM_THREADS", value, 1);
    else
      unsetenv("CCM_THREADS");
  }
  ~ThreadsVariable() {
    if (saved_.empty())
      unsetenv("CCM_THREADS");
    else
      setenv("CCM_THREADS", saved_.c_str(), 1);
  }

 private:
  std::string saved_;
};

}  // namespace

TEST_CASE("The thread count: --threads, then CCM_THREADS, then the automatic count",
          "[threads][cli]") {
  {
    const ThreadsVariable unset(nullptr);
    CHECK(resolve_threads(3, 2) == 3);
    CHECK(resolve_threads(0, 2) == 2);
    CHECK(resolve_threads(0, 0) == 1);
  }
  {
    const ThreadsVariable five("5");
    CHECK(resolve_threads(0, 2) == 5);
    CHECK(resolve_threads(1, 2) == 1);
  }
}

TEST_CASE("A bad thread count is refused", "[threads][cli]") {
  const ThreadsVariable unset(nullptr);
  CHECK_THROWS_WITH(resolve_threads(-1, 2), Catch::Contains("--threads -1"));
  for (const char* bad : {"0", "two", "2x", "-3"}) {
    const ThreadsVariable v(bad);
    CHECK_THROWS_WITH(resolve_threads(0, 2), Catch::Contains("CCM_THREADS"));
  }
  // Refused before the scene is read or the folder made: exit 2, the option named.
  const std::string out = "/tmp/ccm-threads-option-test";
  const std::string err = out + ".stderr";
  const std::string command = std::string(CCM_BINARY) + " run " + CCM_SOURCE_DIR +
                              "/scenes/examples/bar_pulse.toml --out " + out + " --threads -1 2>" +
                              err;
  const int status = std::system(command.c_str());
  CHECK(WEXITSTATUS(status) == 2);
  std::ifstream in(err);
  std::string message, line;
  while (std::getline(in, line)) message += line + "\n";
  CHECK_THAT(message, Catch::Contains("--threads -1"));
  CHECK_FALSE(std::filesystem::exists(out));
  std::filesystem::remove(err);
}
