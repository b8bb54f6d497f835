#include "rig_models/measurement/csv_cells.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdlib>

namespace ccm::rig {
namespace {

std::string_view trim_spaces(std::string_view s) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  return s;
}

}  // namespace

std::vector<std::string_view> split_cells(std::string_view line) { return split_cells(line, ','); }

std::vector<std::string_view> split_cells(std::string_view line, char delimiter) {
  std::vector<std::string_view> cells;
  size_t start = 0;
  while (true) {
    const size_t comma = line.find(delimiter, start);
    cells.push_back(trim_spaces(line.substr(start, comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return cells;
}

std::optional<char> foreign_delimiter(std::string_view cell) {
  for (char c : {';', '\t', '|'})
    if (cell.find(c) != std::string_view::npos) return c;
  return std::nullopt;
}

CellNumber parse_number_cell(std::string_view cell) {
  std::string_view digits = cell;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  double v = 0.0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  if (digits.empty() || end != digits.data() + digits.size() ||
      (ec != std::errc() && ec != std::errc::result_out_of_range))
    return {0.0, fmt::format("non-numeric cell '{}'", cell)};
  if (ec == std::errc::result_out_of_range) {
    // from_chars leaves v alone on overflow and underflow alike; strtod tells them apart.
    const double huge_or_tiny = std::strtod(std::string(digits).c_str(), nullptr);
    if (std::isfinite(huge_or_tiny))
      return {0.0, fmt::format("number '{}' is too small for a double", cell)};
    return {0.0, fmt::format("non-finite number '{}'", cell)};
  }
  if (!std::isfinite(v)) return {0.0, fmt::format("non-finite number '{}'", cell)};
  return {v, {}};
}

}  // namespace ccm::rig
