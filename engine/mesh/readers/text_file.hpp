// A mesh file read whole and split into lines, with the one way readers report a problem in it:
// MeshError "<file>:<line>: <section>: <problem>", so the user can go to the place at once.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ccm {

class TextFile {
 public:
  // Throws MeshError naming the path when it is missing, a directory, unreadable or binary
  // (holds a NUL byte).
  explicit TextFile(const std::filesystem::path& path);

  const std::string& name() const { return name_; }
  int n_lines() const { return static_cast<int>(lines_.size()); }
  // Line i (0-based) without its end-of-line characters.
  std::string_view line(int i) const { return lines_[static_cast<size_t>(i)]; }

  // Throws MeshError "<file>:<i + 1>: <section>: <problem>".
  [[noreturn]] void fail(int i, std::string_view section, std::string_view problem) const;

 private:
  std::string name_;
  std::string text_;
  std::vector<std::string_view> lines_;
};

// The same message for a place remembered after the file was read.
[[noreturn]] void fail_at(const std::string& file, int line_number, std::string_view section,
                          std::string_view problem);

}  // namespace ccm
