// Every input a fuzz target once failed on (tests/data/fuzz/<target>/, kept when the defect was
// fixed: docs/fuzzing.md) replayed through the same entry point the target calls
// (fuzz/fuzz_readers.hpp): each must now be read or refused with the reader's own error. An
// exception of another type aborts the test run, as it aborted the fuzzer.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "fuzz/fuzz_readers.hpp"

namespace fs = std::filesystem;

namespace {

std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("fuzz regressions: every kept input is read or refused by its reader's own error",
          "[fuzz]") {
  const fs::path root = fs::path(CCM_SOURCE_DIR) / "tests" / "data" / "fuzz";
  int replayed = 0;
  for (const auto& target : fs::directory_iterator(root)) {
    if (!target.is_directory()) continue;  // README.md
    const std::string name = target.path().filename().string();
    INFO("target folder " << name);
    const ccm::fuzz::Target* reader = ccm::fuzz::target_named(name);
    REQUIRE(reader != nullptr);  // a folder names a target
    for (const auto& input : fs::directory_iterator(target.path())) {
      INFO("input " << input.path().filename().string());
      reader->read(bytes_of(input.path()));
      ++replayed;
    }
  }
  CHECK(replayed >= 1);
}
