// Strict field parsing for the text mesh readers: a field is a number only if all of it is one.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ccm {

std::string_view trim(std::string_view s);
std::string upper(std::string_view s);

// Whitespace-separated fields.
std::vector<std::string_view> split_whitespace(std::string_view line);
// Comma-separated fields, each trimmed; an empty field after a final comma is dropped.
std::vector<std::string_view> split_commas(std::string_view line);

// An integer that fits in a long, optionally signed.
std::optional<long> parse_integer(std::string_view field);
// A finite decimal number; Fortran exponents (1.0D+00) are accepted.
std::optional<double> parse_real(std::string_view field);

}  // namespace ccm
