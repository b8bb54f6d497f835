#include "engine/mesh/readers/fields.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

namespace ccm {

std::string_view trim(std::string_view s) {
  const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f'; };
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  return out;
}

std::vector<std::string_view> split_whitespace(std::string_view line) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

std::vector<std::string_view> split_commas(std::string_view line) {
  std::vector<std::string_view> out;
  size_t start = 0;
  while (true) {
    const size_t comma = line.find(',', start);
    out.push_back(
        trim(line.substr(start, comma == std::string_view::npos ? comma : comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  if (out.size() > 1 && out.back().empty()) out.pop_back();
  return out;
}

std::optional<long> parse_integer(std::string_view field) {
  if (!field.empty() && field.front() == '+') field.remove_prefix(1);
  long value = 0;
  const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (field.empty() || ec != std::errc() || end != field.data() + field.size()) return std::nullopt;
  return value;
}

std::optional<double> parse_real(std::string_view field) {
  if (!field.empty() && field.front() == '+') field.remove_prefix(1);
  std::array<char, 64> buffer;
  if (field.empty() || field.size() >= buffer.size()) return std::nullopt;
  const auto stop = std::copy(field.begin(), field.end(), buffer.begin());
  std::replace_if(
      buffer.begin(), stop, [](char c) { return c == 'D' || c == 'd'; }, 'E');
  double value = 0;
  const auto [end, ec] = std::from_chars(buffer.data(), stop, value);
  if (ec != std::errc() || end != stop || !std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace ccm
