// A whole text file as a string (empty when it cannot be read). Through rdbuf: GCC 12 warns
// (-Wnull-dereference) on strings built from istreambuf_iterator.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace ccm::test {

inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace ccm::test
