// The cell level of the measured-CSV reader: splitting a line on commas and reading one
// numeric cell, with the defect named when a cell is not a finite number.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ccm::rig {

// The cells of one line, split on ',' (no quoting in this format), spaces trimmed.
std::vector<std::string_view> split_cells(std::string_view line);
// The same on another delimiter (';' or a tab, as loggers in some locales write).
std::vector<std::string_view> split_cells(std::string_view line, char delimiter);

// The delimiter a cell betrays when the file uses another one (';' or a tab), else nullopt.
std::optional<char> foreign_delimiter(std::string_view cell);

// A numeric cell: a finite double (a leading '+' allowed), or the problem with it, worded
// for a message ("non-numeric cell 'x'", "non-finite number 'inf'").
struct CellNumber {
  double value = 0.0;
  std::string problem;  // empty when value is good
};
CellNumber parse_number_cell(std::string_view cell);

}  // namespace ccm::rig
