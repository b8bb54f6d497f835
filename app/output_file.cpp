#include "app/output_file.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace ccm {

void write_atomic(const std::filesystem::path& file, std::string_view content) {
  const std::filesystem::path tmp = file.string() + ".partial";
  {
    std::ofstream out(tmp, std::ios::binary);
    out << content;
    out.close();
    if (!out) throw std::runtime_error(fmt::format("{}: write failed", tmp.string()));
  }
  std::filesystem::rename(tmp, file);
}

void require_writable_output(const std::filesystem::path& out, std::string_view option) {
  std::error_code ec;
  std::filesystem::path existing = std::filesystem::absolute(out, ec);
  while (!existing.empty() && !std::filesystem::exists(existing, ec) &&
         existing != existing.parent_path())
    existing = existing.parent_path();
  if (::access(existing.c_str(), W_OK) != 0)
    throw std::invalid_argument(fmt::format("{} {}: {} is not writable ({})", option, out.string(),
                                            existing.string(), std::strerror(errno)));
}

std::string toml_string(std::string_view s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\')
      out += fmt::format("\\{}", c);
    else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
      out += fmt::format("\\u{:04x}", static_cast<unsigned>(static_cast<unsigned char>(c)));
    else
      out += c;
  }
  return out + "\"";
}

std::string toml_float(double v) {
  std::string s = fmt::format("{}", v);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // "n": inf, nan
  return s;
}

}  // namespace ccm
