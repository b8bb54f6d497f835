// Reads the report's RFC 4180 CSV tables back (quoted fields, doubled quotes), for checks of
// the files `ccm report` writes.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace ccm::test {

using CsvRows = std::vector<std::vector<std::string>>;

// Every record of the text, the header first. Line breaks inside quotes are kept in the field.
CsvRows parse_csv(const std::string& text);

// parse_csv of a file's content; empty when the file cannot be read.
CsvRows read_csv(const std::filesystem::path& file);

}  // namespace ccm::test
