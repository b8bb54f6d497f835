#include "config/did_you_mean.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <vector>

namespace ccm {

size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::string_view closest_name(std::string_view given, std::span<const std::string_view> allowed) {
  std::string_view best;
  size_t best_d = std::numeric_limits<size_t>::max();
  for (std::string_view k : allowed) {
    const size_t d = edit_distance(given, k);
    if (d < best_d) {
      best_d = d;
      best = k;
    }
  }
  return best_d <= 2 && best_d < given.size() ? best : std::string_view();
}

std::string unknown_value_problem(std::string_view given,
                                  std::span<const std::string_view> allowed) {
  std::string quoted;
  for (std::string_view a : allowed)
    quoted += fmt::format("{}\"{}\"", quoted.empty() ? "" : ", ", a);
  const std::string_view best = closest_name(given, allowed);
  if (best.empty()) return fmt::format("must be one of {} (got \"{}\")", quoted, given);
  return fmt::format("must be one of {} (got \"{}\"; did you mean \"{}\"?)", quoted, given, best);
}

}  // namespace ccm
