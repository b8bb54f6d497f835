// What every fuzz target shares (docs/fuzzing.md): the input written to a file of the name a
// reader expects (readers take paths: they resolve relative files and name the file in their
// messages), and the rule that a reader may refuse an input only with its own error type. Any
// other exception is a defect: the command would exit 1 (internal error) where bad input must
// exit 2; it aborts, so that libFuzzer keeps the input.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <typeinfo>

namespace ccm::fuzz {

// A folder of this process's own under the temporary directory, made once, removed at exit.
inline const std::filesystem::path& scratch_dir() {
  static const std::filesystem::path dir = [] {
    auto d = std::filesystem::temp_directory_path() / ("ccm-fuzz-" + std::to_string(getpid()));
    std::filesystem::create_directories(d);
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(scratch_dir(), ec);
    });
    return d;
  }();
  return dir;
}

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// Writes the input to scratch_dir()/name and returns the path.
inline std::filesystem::path write_input(const std::string& name, std::string_view text) {
  const auto file = scratch_dir() / name;
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  return file;
}

// Runs read(); returns normally when it succeeds or throws an Allowed. Aborts on any other
// exception, printing its type and message.
template <class Allowed, class Read>
void expect_only(Read&& read) {
  try {
    read();
  } catch (const Allowed&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ccm fuzz: unexpected %s: %s\n", typeid(e).name(), e.what());
    std::abort();
  }
}

}  // namespace ccm::fuzz
