// Suggestions for a mistyped key or value: the closest allowed name by edit distance.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace ccm {

// Levenshtein distance (insertions, deletions, substitutions).
size_t edit_distance(std::string_view a, std::string_view b);

// The allowed name closest to `given` when it is at most 2 edits away (and `given` is longer
// than the distance), else empty.
std::string_view closest_name(std::string_view given, std::span<const std::string_view> allowed);

// For a string value that is none of `allowed`:
// must be one of "a", "b" (got "x"; did you mean "a"?)
std::string unknown_value_problem(std::string_view given,
                                  std::span<const std::string_view> allowed);

}  // namespace ccm
