#include "engine/mesh/readers/text_file.hpp"

#include <fmt/format.h>

#include <fstream>

#include "engine/mesh/gmsh_mesher.hpp"  // MeshError

namespace ccm {

namespace fs = std::filesystem;

TextFile::TextFile(const fs::path& path) : name_(path.string()) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw MeshError(fmt::format("{}: no such file", name_));
  if (fs::is_directory(path, ec)) throw MeshError(fmt::format("{}: is a directory", name_));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MeshError(fmt::format("{}: cannot be opened for reading", name_));
  const auto size = fs::file_size(path, ec);
  if (ec) throw MeshError(fmt::format("{}: cannot be read", name_));
  text_.resize(size);
  in.read(text_.data(), static_cast<std::streamsize>(size));
  if (static_cast<uintmax_t>(in.gcount()) != size)
    throw MeshError(fmt::format("{}: cannot be read", name_));
  if (text_.find('\0') != std::string::npos)
    throw MeshError(fmt::format("{}: is a binary file, not a text mesh file", name_));
  size_t start = 0;
  while (start < text_.size()) {
    size_t end = text_.find('\n', start);
    if (end == std::string::npos) end = text_.size();
    size_t stop = end;
    if (stop > start && text_[stop - 1] == '\r') --stop;
    lines_.emplace_back(text_.data() + start, stop - start);
    start = end + 1;
  }
}

void TextFile::fail(int i, std::string_view section, std::string_view problem) const {
  fail_at(name_, i + 1, section, problem);
}

void fail_at(const std::string& file, int line_number, std::string_view section,
             std::string_view problem) {
  throw MeshError(fmt::format("{}:{}: {}: {}", file, line_number, section, problem));
}

}  // namespace ccm
